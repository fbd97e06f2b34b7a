//! `snooker impact`: one impact of the thesis's frictional models, in the terms of the thesis's
//! figures (spins in units of V/R), with the state just after the impact and once each ball's
//! slip on the cloth has ended, and an optional plot of the slips against the normal impulse
//! (thesis figs. 6.14, 6.15, 6.23).

use super::bad_input;
use crate::plot;
use anyhow::bail;
use serde_json::{Value, json};
use snooker_engine::impact::ball_ball::mathavan as bb;
use snooker_engine::impact::cushion::mathavan as cush;
use snooker_engine::impact::impulse::Sample;
use snooker_engine::impact::incoming;
use snooker_engine::motion::{self, airborne};
use snooker_engine::sim::setup::MAX_SPIN_SPEED;
use snooker_engine::{
    Ball, BallKind, BallState, Models, Motion, Params, Setup, SimOptions, Table, Vec3, simulate,
};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `snooker impact`.
#[derive(clap::Args)]
pub struct Args {
    #[command(subcommand)]
    which: Kind,
    /// Print the result as JSON.
    #[arg(long, global = true)]
    json: bool,
    /// Draw slip speed and direction against the normal impulse into this PNG.
    #[arg(long, global = true, value_name = "FILE.png")]
    plot: Option<PathBuf>,
    /// Override a parameter, NAME=VALUE with the scene files' names (repeatable).
    #[arg(long = "param", global = true, value_name = "NAME=VALUE")]
    params: Vec<String>,
}

/// The incoming ball of an impact (spins in units of V/R; 1 = rolling).
#[derive(clap::Args)]
struct Incoming {
    /// Speed of the incoming ball, m/s.
    #[arg(long)]
    speed: f64,
    /// Topspin in units of V/R (1 = rolling, negative = backspin).
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    topspin: f64,
    /// Sidespin in units of V/R (positive = anticlockwise seen from above).
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    sidespin: f64,
}

#[derive(clap::Subcommand)]
enum Kind {
    /// A cue ball moving along +x meets a resting object ball.
    BallBall {
        #[command(flatten)]
        incoming: Incoming,
        /// Cut angle, degrees (0 = full ball; positive: object ball to the left).
        #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
        cut: f64,
    },
    /// A ball meets a cushion.
    Cushion {
        #[command(flatten)]
        incoming: Incoming,
        /// Angle of incidence from the cushion line, degrees (90 = perpendicular).
        #[arg(long, default_value_t = 90.0)]
        angle: f64,
    },
}

/// Fastest incoming ball accepted, m/s.
const MAX_SPEED: f64 = 20.0;
/// Largest spin accepted, units of V/R.
const MAX_SPIN: f64 = 10.0;

/// Runs the command.
pub fn run(args: Args) -> ExitCode {
    let (doc, samples, axes) = match impact(&args) {
        Ok(r) => r,
        Err(e) => return bad_input(format!("{e:#}")),
    };
    if args.json {
        outln!(
            "{}",
            serde_json::to_string_pretty(&doc).expect("finite numbers")
        );
    } else {
        out!("{}", text(&doc));
    }
    if let Some(path) = &args.plot {
        if let Err(e) = plot::slips(&samples, axes, path) {
            return bad_input(format!("--plot {}: {e:#}", path.display()));
        }
        if !args.json {
            outln!("plot written to {}", path.display());
        }
    }
    ExitCode::SUCCESS
}

/// One ball's state, as reported.
fn describe(s: &BallState) -> Value {
    let v = Vec3::new(s.vel.x, s.vel.y, 0.0);
    json!({
        "speed": v.norm(),
        "direction_deg": v.y.atan2(v.x).to_degrees(),
        "vertical_speed": s.vel.z,
        "spin": [s.spin.x, s.spin.y, s.spin.z],
        "sidespin": s.spin.z,
        "motion": s.motion.name(),
    })
}

/// What happens to a ball after an impact until its slip on the cloth ends, run by the engine
/// on the open table: its hop, if it left the cloth, then its slide. The ball's state once its
/// slip has ended (rolling, spinning or at rest; still sliding if the cloth has no friction),
/// the hop's peak height and length, and the distance covered until then.
fn after_slip(s: BallState, p: &Params) -> anyhow::Result<(BallState, f64, f64, f64)> {
    let setup = Setup {
        table: Table::open(),
        params: *p,
        models: Models::default(),
        balls: vec![Ball {
            id: "ball".into(),
            kind: BallKind::Other,
            state: s,
        }],
    };
    let opts = SimOptions {
        horizon: Some(SimOptions::default().max_time),
        ..SimOptions::default()
    };
    let shot = simulate(&setup, &opts)?;
    let segments = &shot.tracks[0].segments;
    let first = segments[0].state;
    let (hop_height, hop_length) = if first.motion == Motion::Airborne {
        let landed = segments[1..].first().map_or(first.pos, |g| g.state.pos);
        let length = Vec3::new(landed.x - first.pos.x, landed.y - first.pos.y, 0.0).norm();
        (airborne::peak_height(&first, p), length)
    } else {
        (0.0, 0.0)
    };
    let end = segments
        .iter()
        .find(|g| !matches!(g.state.motion, Motion::Sliding | Motion::Airborne))
        .map_or_else(|| shot.final_states()[0], |g| g.state);
    let dist = Vec3::new(end.pos.x - s.pos.x, end.pos.y - s.pos.y, 0.0).norm();
    Ok((end, hop_height, hop_length, dist))
}

/// The report of one ball after the impact.
fn ball_report(s: BallState, p: &Params) -> anyhow::Result<serde_json::Map<String, Value>> {
    let (rolled, hop_height, hop_length, dist) = after_slip(s, p)?;
    let mut m = serde_json::Map::new();
    m.insert("after_impact".into(), describe(&motion::settle(s, p)));
    m.insert("after_slip".into(), describe(&rolled));
    m.insert("hop_height".into(), json!(hop_height));
    m.insert("hop_length".into(), json!(hop_length));
    m.insert("distance_to_end_of_slip".into(), json!(dist));
    Ok(m)
}

/// The result document, the samples for a plot and their axes.
fn impact(args: &Args) -> anyhow::Result<(Value, Vec<Sample>, plot::SlipAxes)> {
    let p = snooker_scene::override_params(Params::default(), &args.params)?;
    let (inc, angle) = match &args.which {
        Kind::BallBall { incoming, cut } => (incoming, *cut),
        Kind::Cushion { incoming, angle } => (incoming, *angle),
    };
    let speed = inc.speed;
    if !(speed.is_finite() && speed > 0.0 && speed <= MAX_SPEED) {
        bail!("--speed must lie in (0, {MAX_SPEED}] m/s, got {speed}");
    }
    for (name, v) in [("--topspin", inc.topspin), ("--sidespin", inc.sidespin)] {
        if !(v.is_finite() && v.abs() <= MAX_SPIN) {
            bail!("{name} must lie in [-{MAX_SPIN}, {MAX_SPIN}] (units of V/R), got {v}");
        }
    }
    let surface = speed * inc.topspin.hypot(inc.sidespin);
    if surface > MAX_SPIN_SPEED {
        bail!(
            "--speed {speed} with these spins gives the ball a surface speed R|w| of {surface} \
             m/s, beyond any shot (at most {MAX_SPIN_SPEED} m/s)"
        );
    }
    let mut trace = Vec::new();
    let mut doc = serde_json::Map::new();
    let axes: plot::SlipAxes;
    let setup = match &args.which {
        Kind::BallBall { .. } => {
            if !(angle.is_finite() && angle.abs() < 89.0) {
                bail!("--cut must lie in (-89, 89) degrees");
            }
            let (cue, obj) =
                incoming::ball_ball(speed, angle.to_radians(), inc.topspin, inc.sidespin, &p);
            let out = bb::solve(&cue, &obj, &p, Some(&mut trace))?;
            let after = |s: &BallState, i: usize| BallState {
                vel: out.after.vel[i],
                spin: out.after.spin[i],
                ..*s
            };
            let n = (obj.pos - cue.pos).normalize();
            axes = (n.cross(&Vec3::z()).normalize(), Vec3::z());
            doc.insert("cue_ball".into(), ball_report(after(&cue, 0), &p)?.into());
            doc.insert(
                "object_ball".into(),
                ball_report(after(&obj, 1), &p)?.into(),
            );
            doc.insert("impulse".into(), json!(out.impulse));
            "ball-ball"
        }
        Kind::Cushion { .. } => {
            if !(angle.is_finite() && angle > 0.0 && angle <= 90.0) {
                bail!("--angle must lie in (0, 90] degrees");
            }
            let rad = angle.to_radians();
            let ball = incoming::cushion(speed, rad, inc.topspin, inc.sidespin, &p);
            let out = cush::solve(&ball, Vec3::y(), &p, Some(&mut trace))?;
            let b1 = BallState {
                vel: out.after.vel[0],
                spin: out.after.spin[0],
                ..ball
            };
            let n = cush::contact(&ball, Vec3::y(), &p).normal;
            axes = (Vec3::x(), n.cross(&Vec3::x()));
            let mut report = ball_report(b1, &p)?;
            report.insert(
                "rebound_angle_deg".into(),
                json!(b1.vel.y.atan2(b1.vel.x.abs()).to_degrees()),
            );
            doc.insert("ball".into(), report.into());
            doc.insert("impulse".into(), json!(out.impulse));
            doc.insert("normal_speed".into(), json!(speed * rad.sin()));
            "cushion"
        }
    };
    let input = json!({
        "setup": setup,
        "speed": speed,
        "angle_deg": angle,
        "topspin_v_over_r": inc.topspin,
        "sidespin_v_over_r": inc.sidespin,
        "mu_ball": p.mu_ball, "e_ball": p.e_ball, "mu_cushion": p.mu_cushion,
        "e_cushion": p.e_cushion, "mu_slide": p.mu_slide,
    });
    let mut out = serde_json::Map::new();
    out.insert("input".into(), input);
    out.extend(doc);
    out.insert(
        "units".into(),
        json!("SI; directions in degrees from the incoming ball's path (ball-ball) or the cushion line (cushion)"),
    );
    Ok((Value::Object(out), trace, axes))
}

/// A text rendering of the result document.
fn text(doc: &Value) -> String {
    let mut s = String::new();
    let input = &doc["input"];
    let _ = writeln!(
        s,
        "{} impact at {:.3} m/s, {:.2} deg, topspin {} V/R, sidespin {} V/R",
        input["setup"].as_str().unwrap_or("?"),
        input["speed"].as_f64().unwrap_or(0.0),
        input["angle_deg"].as_f64().unwrap_or(0.0),
        input["topspin_v_over_r"],
        input["sidespin_v_over_r"]
    );
    for ball in ["cue_ball", "object_ball", "ball"] {
        let b = &doc[ball];
        if b.is_null() {
            continue;
        }
        let _ = writeln!(s, "{}:", ball.replace('_', " "));
        for (label, key) in [
            ("  after the impact", "after_impact"),
            ("  after the slip  ", "after_slip"),
        ] {
            let st = &b[key];
            let spin: Vec<f64> = st["spin"]
                .as_array()
                .map(|a| a.iter().filter_map(|x| x.as_f64()).collect())
                .unwrap_or_default();
            let _ = writeln!(
                s,
                "{label}: speed {:.4} m/s, direction {:+.2} deg, spin ({:.2}, {:.2}, {:.2}) rad/s, {}",
                st["speed"].as_f64().unwrap_or(0.0),
                st["direction_deg"].as_f64().unwrap_or(0.0),
                spin.first().copied().unwrap_or(0.0),
                spin.get(1).copied().unwrap_or(0.0),
                spin.get(2).copied().unwrap_or(0.0),
                st["motion"].as_str().unwrap_or("?")
            );
        }
        let h = b["hop_height"].as_f64().unwrap_or(0.0);
        if h > 0.0 {
            let _ = writeln!(
                s,
                "  hop: {:.3} mm high, {:.1} mm long",
                h * 1e3,
                b["hop_length"].as_f64().unwrap_or(0.0) * 1e3
            );
        }
        let _ = writeln!(
            s,
            "  slip ends {:.1} mm from the impact",
            b["distance_to_end_of_slip"].as_f64().unwrap_or(0.0) * 1e3
        );
    }
    let _ = writeln!(
        s,
        "normal impulse: {:.6} N s",
        doc["impulse"].as_f64().unwrap_or(0.0)
    );
    s
}
