//! `snooker impact`: one impact of the thesis's frictional models, in the terms of the thesis's
//! figures (spins in units of V/R), with the state just after the impact and once each ball's
//! slip on the cloth has ended, and an optional plot of the slips against the normal impulse
//! (thesis figs. 6.14, 6.15, 6.23).

use super::bad_input;
use crate::plot;
use serde_json::Value;
use snooker_engine::Params;
use snooker_engine::impact::impulse::Sample;
use snooker_scene::impact_report::{Geometry, ImpactSpec, impact_report};
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

/// The result document (the scene crate's impact report), the samples for a plot and their
/// axes.
fn impact(args: &Args) -> anyhow::Result<(Value, Vec<Sample>, plot::SlipAxes)> {
    let params = snooker_scene::override_params(Params::default(), &args.params)?;
    let (inc, geometry) = match &args.which {
        Kind::BallBall { incoming, cut } => (incoming, Geometry::BallBall { cut: *cut }),
        Kind::Cushion { incoming, angle } => (incoming, Geometry::Cushion { angle: *angle }),
    };
    let spec = ImpactSpec {
        geometry,
        speed: inc.speed,
        topspin: inc.topspin,
        sidespin: inc.sidespin,
        params,
    };
    let mut trace = Vec::new();
    let report = impact_report(&spec, Some(&mut trace))?;
    Ok((report.doc, trace, report.axes))
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
