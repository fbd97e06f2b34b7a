//! `snooker impact`: one impact of the thesis's frictional models, in the terms of the thesis's
//! figures (spins in units of V/R), with the state just after the impact and once each ball's
//! slip on the cloth has ended, and an optional plot of the slips against the normal impulse
//! (thesis figs. 6.14, 6.15, 6.23).

use super::{bad_input, spec};
use crate::{output, plot};
use anyhow::Context;
use snooker_engine::Params;
use snooker_engine::impact::impulse::Sample;
use snooker_scene::impact_report::{Geometry, ImpactRecord, ImpactSpec, impact_report};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
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
    if let Some(path) = &args.plot
        && let Err(e) = check_plot(path)
    {
        return bad_input(format!("--plot {}: {e}", path.display()));
    }
    let (doc, samples, axes) = match impact(&args) {
        Ok(r) => r,
        Err(e) => return bad_input(e),
    };
    // The plot first: a plot that cannot be drawn leaves nothing printed.
    if let Some(path) = &args.plot
        && let Err(e) = draw(&samples, axes, path)
    {
        return bad_input(format!("--plot {}: {e:#}", path.display()));
    }
    if args.json {
        outln!(
            "{}",
            serde_json::to_string_pretty(&doc).expect("finite numbers")
        );
    } else {
        out!("{}", text(&doc));
    }
    if let Some(path) = &args.plot
        && !args.json
    {
        outln!("plot written to {}", path.display());
    }
    ExitCode::SUCCESS
}

/// Checks, before any work, that the plot can be written to `path`: a PNG file's name, and a
/// path that can become a file.
fn check_plot(path: &Path) -> Result<(), String> {
    let png = path
        .extension()
        .is_some_and(|x| x.eq_ignore_ascii_case("png"));
    if !png {
        return Err("the plot is a PNG: its name must end in .png".into());
    }
    output::check_output(path).map_err(|e| e.to_string())
}

/// Draws the plot into a temporary PNG beside `path` (missing directories created) and puts it
/// in place: nothing is left half-drawn. A link is drawn through, as every output is.
fn draw(samples: &[Sample], axes: plot::SlipAxes, path: &Path) -> anyhow::Result<()> {
    let path = &output::link_chain(path)
        .pop()
        .expect("the chain holds the path");
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let name = path.file_name().context("no file name")?.to_string_lossy();
    let tmp = dir.join(format!(".{name}.tmp.png"));
    let done = plot::slips(samples, axes, &tmp).and_then(|()| {
        std::fs::rename(&tmp, path).with_context(|| format!("cannot write {}", path.display()))
    });
    if done.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    done
}

/// The result document (the scene crate's impact report), the samples for a plot and their
/// axes.
fn impact(args: &Args) -> Result<(ImpactRecord, Vec<Sample>, plot::SlipAxes), String> {
    let params = spec::params(Params::default(), &args.params)?;
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
    let report = impact_report(&spec, Some(&mut trace)).map_err(|e| match e.field() {
        // The message begins with the input's name: the command's flag for it.
        Some(_) => format!("--{e}"),
        None => e.to_string(),
    })?;
    Ok((report.doc, trace, report.axes))
}

/// A text rendering of the result document.
fn text(doc: &ImpactRecord) -> String {
    let mut s = String::new();
    let input = &doc.input;
    let _ = writeln!(
        s,
        "{} impact at {:.3} m/s, {:.2} deg, topspin {:?} V/R, sidespin {:?} V/R",
        input.setup, input.speed, input.angle_deg, input.topspin_v_over_r, input.sidespin_v_over_r
    );
    for (name, ball) in [
        ("cue ball", &doc.cue_ball),
        ("object ball", &doc.object_ball),
        ("ball", &doc.ball),
    ] {
        let Some(b) = ball else { continue };
        let _ = writeln!(s, "{name}:");
        for (label, st) in [
            ("  after the impact", &b.after_impact),
            ("  after the slip  ", &b.after_slip),
        ] {
            let _ = writeln!(
                s,
                "{label}: speed {:.4} m/s, direction {:+.2} deg, spin ({:.2}, {:.2}, {:.2}) rad/s, {}",
                st.speed,
                st.direction_deg,
                st.spin[0],
                st.spin[1],
                st.spin[2],
                st.motion.name()
            );
        }
        if b.hop_height > 0.0 {
            let _ = writeln!(
                s,
                "  hop: {:.3} mm high, {:.1} mm long",
                b.hop_height * 1e3,
                b.hop_length * 1e3
            );
        }
        let _ = writeln!(
            s,
            "  slip ends {:.1} mm from the impact",
            b.distance_to_end_of_slip * 1e3
        );
    }
    let _ = writeln!(s, "normal impulse: {:.6} N s", doc.impulse);
    s
}
