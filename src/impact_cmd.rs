//! `snooker impact`: one impact of the thesis's frictional models, in the terms of the thesis's
//! figures (spins in units of V/R), with the state just after the impact and once each ball's
//! slip on the cloth has ended, and an optional plot of the slips against the normal impulse
//! (thesis figs. 6.14, 6.15, 6.23).

use anyhow::{Context, bail};
use serde_json::{Value, json};
use snooker_engine::impact::ball_ball::mathavan as bb;
use snooker_engine::impact::cushion::mathavan as cush;
use snooker_engine::impact::impulse::Sample;
use snooker_engine::motion::{self, Transition};
use snooker_engine::{BallState, Motion, Params, Vec3};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Which impact, set up as in the thesis's figures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Setup {
    /// The cue ball moves along +x at `speed` and meets the object ball at cut angle `cut`
    /// (rad; the line of centres at `cut` from +x, object ball to the left).
    BallBall {
        /// Cue ball speed, m/s.
        speed: f64,
        /// Cut angle, rad.
        cut: f64,
    },
    /// The ball meets a cushion at `angle` (rad) from the cushion line.
    Cushion {
        /// Ball speed, m/s.
        speed: f64,
        /// Angle of incidence from the cushion line, rad.
        angle: f64,
    },
}

/// A request: the impact, the incoming spins and the parameters.
#[derive(Clone, Debug)]
pub struct Request {
    /// The impact.
    pub setup: Setup,
    /// Topspin of the incoming ball in units of V/R (1 = rolling, negative = backspin).
    pub topspin: f64,
    /// Sidespin in units of V/R (positive = anticlockwise seen from above).
    pub sidespin: f64,
    /// Parameter overrides, `NAME=VALUE` with the scene files' names.
    pub params: Vec<String>,
    /// Print JSON instead of text.
    pub json: bool,
    /// Write a plot of the slips against the impulse to this PNG file.
    pub plot: Option<PathBuf>,
}

/// Applies `NAME=VALUE` overrides to the default parameters.
pub fn parameters(overrides: &[String]) -> anyhow::Result<Params> {
    crate::scene::override_params(Params::default(), overrides)
}

/// One ball's state, as reported.
fn describe(s: &BallState, reference: f64) -> Value {
    let v = Vec3::new(s.vel.x, s.vel.y, 0.0);
    json!({
        "speed": v.norm(),
        "direction_deg": (v.y.atan2(v.x) - reference).to_degrees(),
        "vertical_speed": s.vel.z,
        "spin": [s.spin.x, s.spin.y, s.spin.z],
        "sidespin": s.spin.z,
        "motion": s.motion.name(),
    })
}

/// What happens to a ball after the impact until its slip on the cloth ends: the hop (if it
/// left the cloth), then sliding; returns the state once rolling (or at rest), the hop's
/// height and length, and the distance covered until then.
fn after_slip(s: BallState, p: &Params) -> (BallState, f64, f64, f64) {
    let mut s = motion::settle(s, p);
    let start = s.pos;
    let (mut hop_height, mut hop_length) = (0.0, 0.0);
    // A few phases (a hop, a landing, the slide), or many short segments with the cloth's
    // extra effects on (one per 10 ms of sliding).
    for _ in 0..100_000 {
        match s.motion {
            Motion::Airborne => {
                let t = motion::duration(&s, p);
                hop_height = s.vel.z * s.vel.z / (2.0 * p.g);
                hop_length = Vec3::new(s.vel.x, s.vel.y, 0.0).norm() * t;
                let end = motion::state_at(&s, t, p);
                s = motion::finish(&s, &end, p).map_or(end, |(_, n)| n);
            }
            Motion::Sliding => {
                let end = motion::state_at(&s, motion::duration(&s, p), p);
                let (kind, next) = motion::finish(&s, &end, p).expect("sliding ends");
                s = next;
                if kind == Transition::SlideToRoll {
                    break;
                }
            }
            _ => break,
        }
    }
    let dist = Vec3::new(s.pos.x - start.x, s.pos.y - start.y, 0.0).norm();
    (s, hop_height, hop_length, dist)
}

/// The axes in which the slip between the bodies is measured, as in the thesis: for ball-ball
/// X horizontal across the line of centres and Z up (eq. 6.7); for the cushion X along the
/// cushion and Y' up its face (eq. 6.25).
pub type Axes = (Vec3, Vec3);

/// Runs the request: the result document, the samples for a plot and their axes.
pub fn run(req: &Request) -> anyhow::Result<(Value, Vec<Sample>, Axes)> {
    let p = parameters(&req.params)?;
    let r = p.ball_radius;
    let mut trace = Vec::new();
    let (speed, angle) = match req.setup {
        Setup::BallBall { speed, cut } => (speed, cut),
        Setup::Cushion { speed, angle } => (speed, angle),
    };
    if !(speed.is_finite() && speed > 0.0 && speed <= 20.0) {
        bail!("--speed must lie in (0, 20] m/s, got {speed}");
    }
    for (name, v) in [("--topspin", req.topspin), ("--sidespin", req.sidespin)] {
        if !(v.is_finite() && v.abs() <= 10.0) {
            bail!("{name} must lie in [-10, 10] (units of V/R), got {v}");
        }
    }
    let mut doc = serde_json::Map::new();
    let axes: Axes;
    match req.setup {
        Setup::BallBall { speed, cut } => {
            if !(cut.is_finite() && cut.abs() < 89f64.to_radians()) {
                bail!("--cut must lie in (-89, 89) degrees");
            }
            let vel = Vec3::new(speed, 0.0, 0.0);
            let cue = BallState {
                pos: Vec3::new(0.0, 0.0, r),
                vel,
                spin: req.topspin * Vec3::z().cross(&vel) / r
                    + Vec3::new(0.0, 0.0, req.sidespin * speed / r),
                motion: Motion::Sliding,
            };
            let obj = BallState::at_rest(2.0 * r * cut.cos(), 2.0 * r * cut.sin(), r);
            let out =
                bb::solve(&cue, &obj, &p, Some(&mut trace)).map_err(|e| anyhow::anyhow!("{e}"))?;
            let after = [out.after.vel, out.after.spin];
            let c1 = BallState {
                vel: after[0][0],
                spin: after[1][0],
                ..cue
            };
            let o1 = BallState {
                vel: after[0][1],
                spin: after[1][1],
                ..obj
            };
            let n = (obj.pos - cue.pos).normalize();
            axes = (n.cross(&Vec3::z()).normalize(), Vec3::z());
            for (name, s) in [("cue_ball", c1), ("object_ball", o1)] {
                let (rolled, hop_h, hop_l, dist) = after_slip(s, &p);
                doc.insert(
                    name.into(),
                    json!({
                        "after_impact": describe(&motion::settle(s, &p), 0.0),
                        "after_slip": describe(&rolled, 0.0),
                        "hop_height": hop_h,
                        "hop_length": hop_l,
                        "distance_to_end_of_slip": dist,
                    }),
                );
            }
            doc.insert("impulse".into(), json!(out.impulse));
        }
        Setup::Cushion { speed, angle } => {
            if !(angle.is_finite() && angle > 0.0 && angle <= std::f64::consts::FRAC_PI_2) {
                bail!("--angle must lie in (0, 90] degrees");
            }
            let vel = speed * Vec3::new(angle.cos(), -angle.sin(), 0.0);
            let ball = BallState {
                pos: Vec3::new(0.0, p.cushion_contact_distance(), r),
                vel,
                spin: req.topspin * Vec3::z().cross(&vel) / r
                    + Vec3::new(0.0, 0.0, req.sidespin * speed / r),
                motion: Motion::Sliding,
            };
            let out = cush::solve(&ball, Vec3::y(), &p, Some(&mut trace))
                .map_err(|e| anyhow::anyhow!("{e}"))?;
            let b1 = BallState {
                vel: out.after.vel[0],
                spin: out.after.spin[0],
                ..ball
            };
            let n = cush::contact(&ball, Vec3::y(), &p).normal;
            axes = (Vec3::x(), n.cross(&Vec3::x()));
            let (rolled, hop_h, hop_l, dist) = after_slip(b1, &p);
            doc.insert(
                "ball".into(),
                json!({
                    "after_impact": describe(&motion::settle(b1, &p), 0.0),
                    "after_slip": describe(&rolled, 0.0),
                    "hop_height": hop_h,
                    "hop_length": hop_l,
                    "distance_to_end_of_slip": dist,
                    "rebound_angle_deg": b1.vel.y.atan2(b1.vel.x.abs()).to_degrees(),
                }),
            );
            doc.insert("impulse".into(), json!(out.impulse));
            doc.insert("normal_speed".into(), json!(speed * angle.sin()));
        }
    }
    let input = json!({
        "setup": match req.setup { Setup::BallBall { .. } => "ball-ball", Setup::Cushion { .. } => "cushion" },
        "speed": speed,
        "angle_deg": angle.to_degrees(),
        "topspin_v_over_r": req.topspin,
        "sidespin_v_over_r": req.sidespin,
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
pub fn text(doc: &Value) -> String {
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

/// Loads a TrueType font for the plot's text from the system (DejaVu Sans, or any font
/// fontconfig would offer under /usr/share/fonts).
pub(crate) fn register_font() -> anyhow::Result<()> {
    let candidates = [
        "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
        "/usr/share/fonts/TTF/DejaVuSans.ttf",
        "/usr/share/fonts/dejavu/DejaVuSans.ttf",
    ];
    let path = candidates
        .iter()
        .map(Path::new)
        .find(|p| p.exists())
        .context("no TrueType font found for the plot's text (install fonts-dejavu-core)")?;
    let bytes: &'static [u8] = Box::leak(std::fs::read(path)?.into_boxed_slice());
    plotters::style::register_font("sans-serif", plotters::style::FontStyle::Normal, bytes)
        .map_err(|_| anyhow::anyhow!("{} is not a usable font", path.display()))?;
    Ok(())
}

/// Draws slip speed and slip direction against the normal impulse for the contact between the
/// bodies and the cloth contacts (thesis figs. 6.14, 6.15, 6.23).
pub fn plot(samples: &[Sample], axes: Axes, path: &Path) -> anyhow::Result<()> {
    use plotters::prelude::*;
    register_font()?;
    if samples.len() < 2 {
        bail!("too few samples to plot");
    }
    let (x_axis, y_axis) = axes;
    let series = |f: &dyn Fn(&Sample) -> f64| {
        samples
            .iter()
            .map(|s| (s.impulse, f(s)))
            .collect::<Vec<_>>()
    };
    let angle =
        |v: Vec3, x: Vec3, y: Vec3| v.dot(&y).atan2(v.dot(&x)).to_degrees().rem_euclid(360.0);
    let slip = series(&|s| s.slip.norm());
    let phi = series(&|s| angle(s.slip, x_axis, y_axis));
    // A cloth slip is drawn only where the cloth holds that ball (a ball in the air has none).
    let cloth = |i: usize| {
        samples
            .iter()
            .filter(|s| s.pressed[i])
            .map(|s| (s.impulse, s.cloth_slip[i].norm()))
            .collect::<Vec<_>>()
    };
    let cloth_phi = |i: usize| {
        samples
            .iter()
            .filter(|s| s.pressed[i])
            .map(|s| (s.impulse, angle(s.cloth_slip[i], Vec3::x(), Vec3::y())))
            .collect::<Vec<_>>()
    };
    let p_max = samples.last().map_or(1.0, |s| s.impulse);
    let root = BitMapBackend::new(path, (1000, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let (top, bottom) = root.split_vertically(350);
    let s_max = samples
        .iter()
        .flat_map(|s| {
            [
                s.slip.norm(),
                s.cloth_slip[0].norm(),
                s.cloth_slip[1].norm(),
            ]
        })
        .fold(0.0f64, f64::max)
        * 1.1;
    let mut c = ChartBuilder::on(&top)
        .caption("slip speed against normal impulse", ("sans-serif", 20))
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(55)
        .build_cartesian_2d(0.0..p_max, 0.0..s_max.max(1e-9))?;
    c.configure_mesh()
        .x_desc("P_I (N s)")
        .y_desc("slip (m/s)")
        .draw()?;
    let colours = [RED, BLUE, GREEN];
    let labels = [
        "s: contact between the bodies",
        "s': cloth under body 0",
        "s': cloth under body 1",
    ];
    let data = [slip, cloth(0), cloth(1)];
    for (k, d) in data.iter().enumerate() {
        if d.iter().all(|p| p.1 == 0.0) {
            continue;
        }
        let d = d.clone();
        let col = colours[k];
        c.draw_series(LineSeries::new(d, col.stroke_width(2)))?
            .label(labels[k])
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col));
    }
    c.configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    let mut c = ChartBuilder::on(&bottom)
        .caption("slip direction against normal impulse", ("sans-serif", 20))
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(55)
        .build_cartesian_2d(0.0..p_max, 0.0..360.0)?;
    c.configure_mesh()
        .x_desc("P_I (N s)")
        .y_desc("direction (deg)")
        .draw()?;
    let dirs = [phi, cloth_phi(0), cloth_phi(1)];
    for (k, d) in dirs.iter().enumerate() {
        if data[k].iter().all(|p| p.1 == 0.0) {
            continue;
        }
        // Directions of slips that have stopped carry no meaning: leave them out.
        let shown: Vec<(f64, f64)> = d
            .iter()
            .zip(&data[k])
            .filter(|(_, s)| s.1 > 1e-6 * s_max)
            .map(|(a, _)| *a)
            .collect();
        c.draw_series(
            shown
                .iter()
                .map(|&(x, y)| Circle::new((x, y), 2, colours[k].filled())),
        )?;
    }
    root.present()
        .with_context(|| format!("cannot write {}", path.display()))?;
    Ok(())
}
