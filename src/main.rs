//! `snooker`: simulate snooker shots from scene files.

use clap::{Parser, Subcommand};
use snooker::{discrepancy_cmd, impact_cmd, output, record, scene, validate_cmd};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    version,
    about = "Event-driven snooker physics engine (SI units, table frame)"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Simulate a scene and print a summary (the built-in break-off when no scene is given).
    Simulate {
        /// Scene file (TOML); see the README for the format.
        scene: Option<PathBuf>,
        /// Write the result as JSON to this file, or to standard output with `-`.
        #[arg(long, value_name = "OUT")]
        json: Option<String>,
        /// Print nothing but errors (and the JSON if it goes to standard output).
        #[arg(long, short)]
        quiet: bool,
        /// Write a Rerun recording of the shot to this file (open it with `rerun OUT.rrd`,
        /// viewer `pip install rerun-sdk==0.36.3`; see docs/recording.md).
        #[arg(long, value_name = "OUT.rrd")]
        record: Option<PathBuf>,
        /// Sample rate of the recording, Hz (every event instant is sampled as well).
        #[arg(long, value_name = "HZ", default_value_t = record::DEFAULT_RATE, requires = "record")]
        record_rate: f64,
    },
    /// One impact of the thesis's frictional models (chapter 6): the state just after it and
    /// once the slip on the cloth has ended. Spins in units of V/R as in the thesis's figures.
    Impact {
        #[command(subcommand)]
        which: ImpactKind,
        /// Print the result as JSON.
        #[arg(long, global = true)]
        json: bool,
        /// Draw slip speed and direction against the normal impulse into this PNG.
        #[arg(long, global = true, value_name = "FILE.png")]
        plot: Option<PathBuf>,
        /// Override a parameter, NAME=VALUE with the scene files' names (repeatable).
        #[arg(long = "param", global = true, value_name = "NAME=VALUE")]
        params: Vec<String>,
    },
    /// Cross-check the engine against rapier on the validation scenes (or the given ones) and
    /// print the report; exits with 1 when a verdict fails.
    Validate {
        /// A scene file to check (repeatable); the built-in validation set when none is given.
        #[arg(long = "scene", value_name = "S")]
        scenes: Vec<PathBuf>,
        /// Write the report as JSON to this file.
        #[arg(long, value_name = "OUT")]
        json: Option<PathBuf>,
        /// Write the report as Markdown to this file (docs/validation.md).
        #[arg(long, value_name = "OUT")]
        markdown: Option<PathBuf>,
        /// rapier's time step, s.
        #[arg(long, default_value_t = snooker_validation::crosscheck::DEFAULT_DT)]
        dt: f64,
        /// Also run the time-step study (several minutes).
        #[arg(long)]
        convergence: bool,
    },
    /// Make measured-like data with effects hidden in it: the scene simulated under its model
    /// plus the hidden effects, filmed with camera noise and dropped frames.
    Synth {
        /// The scene the shot starts from (its model is the one without the hidden effects).
        scene: PathBuf,
        /// Hide an effect: a catalogue id with its value(s), e.g. table_slope=0.001,-0.0005,
        /// or one outside the catalogue (wobble=AMPLITUDE_M). Repeatable.
        #[arg(long = "effect", value_name = "NAME=VALUE[,VALUE]")]
        effects: Vec<String>,
        /// Override a parameter of the truth model, NAME=VALUE (repeatable).
        #[arg(long = "param", value_name = "NAME=VALUE")]
        params: Vec<String>,
        /// Camera frames per second.
        #[arg(long, default_value_t = 100.0)]
        fps: f64,
        /// Camera position noise, 1-sigma per coordinate, millimetres.
        #[arg(long, value_name = "MM", default_value_t = 0.5)]
        noise: f64,
        /// Seed of the noise and the dropped frames.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Share of frames lost.
        #[arg(long, default_value_t = 0.02)]
        drop: f64,
        /// Longest recording, s.
        #[arg(long, default_value_t = 20.0)]
        duration: f64,
        /// Initial quantities the data file asks to fit, comma-separated (default: the
        /// strike's speed, or every moving ball's vel and spin).
        #[arg(long, value_delimiter = ',', value_name = "LIST")]
        fit: Option<Vec<String>>,
        /// The data file to write (DATA.toml; the tracks DATA.csv and the scene
        /// DATA.scene.toml go beside it).
        #[arg(short = 'o', long = "out", value_name = "DATA.toml")]
        out: PathBuf,
    },
    /// Find where simulation and measurement disagree, name the missing physical effects from
    /// the catalogue, add them and show the gap shrink.
    Discrepancy {
        /// The measured data file (TOML; see the README).
        data: PathBuf,
        /// A model file ([params] and [models] as in a scene) to start from instead of the
        /// scenes' own model.
        #[arg(long, value_name = "FILE")]
        model: Option<PathBuf>,
        /// Write the full report (JSON, summary, plots) into this directory.
        #[arg(long, value_name = "DIR")]
        report: Option<PathBuf>,
        /// Write the JSON report to this file.
        #[arg(long, value_name = "OUT")]
        json: Option<PathBuf>,
        /// Print nothing but errors.
        #[arg(long, short)]
        quiet: bool,
    },
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

#[derive(Subcommand)]
enum ImpactKind {
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

/// Exit code for bad input (scene file, arguments).
const BAD_INPUT: u8 = 2;
/// Exit code for a simulation that could not finish.
const SIM_FAILED: u8 = 1;

fn simulate(
    scene_path: Option<PathBuf>,
    json: Option<String>,
    quiet: bool,
    recording: Option<(PathBuf, record::RecordOptions)>,
) -> ExitCode {
    let loaded = match &scene_path {
        Some(p) => scene::load(p),
        None => scene::parse(scene::DEFAULT_SCENE, scene::DEFAULT_SCENE_FILE),
    };
    let scene = match loaded {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(BAD_INPUT);
        }
    };
    if let Some(out) = json.as_deref().filter(|o| *o != "-")
        && let Err(e) = output::check_output(Path::new(out))
    {
        eprintln!("error: --json {out}: {e}");
        return ExitCode::from(BAD_INPUT);
    }
    if let Some((out, opts)) = &recording {
        if let Err(e) = output::check_output(out) {
            eprintln!("error: --record {}: {e}", out.display());
            return ExitCode::from(BAD_INPUT);
        }
        if let Err(e) = opts.validate() {
            eprintln!("error: --record-rate {}: {e}", opts.rate);
            return ExitCode::from(BAD_INPUT);
        }
    }
    let shot = match snooker_engine::simulate(&scene.setup, &scene.options) {
        Ok(s) => s,
        Err(e) => {
            eprintln!(
                "error: {}: {e}",
                scene_path
                    .as_deref()
                    .map_or(scene::DEFAULT_SCENE_FILE.into(), |p| p
                        .display()
                        .to_string())
            );
            return ExitCode::from(SIM_FAILED);
        }
    };
    let json_to_stdout = json.as_deref() == Some("-");
    if !quiet {
        let text = output::summary(&scene, &shot);
        if json.as_deref() == Some("-") {
            eprint!("{text}");
        } else {
            print!("{text}");
        }
    }
    // The recording is made before anything is written, so that a failure leaves no result.
    let recording = match recording {
        None => None,
        Some((out, opts)) => match record::encode(&scene, &shot, &opts) {
            Ok(bytes) => Some((out, bytes)),
            Err(e @ (record::RecordError::Rate(_) | record::RecordError::TooLarge(_))) => {
                eprintln!("error: --record {}: {e}", out.display());
                return ExitCode::from(BAD_INPUT);
            }
            Err(e) => {
                eprintln!("error: --record {}: {e}", out.display());
                return ExitCode::from(SIM_FAILED);
            }
        },
    };
    if let Some(out) = json {
        let doc = output::result_json(&scene, &shot);
        let text = serde_json::to_string_pretty(&doc).expect("JSON of finite numbers");
        if out == "-" {
            let mut stdout = std::io::stdout().lock();
            if writeln!(stdout, "{text}").is_err() {
                return ExitCode::from(SIM_FAILED);
            }
        } else if let Err(e) = output::write_atomic(Path::new(&out), (text + "\n").as_bytes()) {
            eprintln!("error: --json {out}: {e:#}");
            return ExitCode::from(BAD_INPUT);
        } else if !quiet {
            println!("result written to {out}");
        }
    }
    if let Some((out, bytes)) = recording {
        if let Err(e) = output::write_atomic(&out, &bytes) {
            eprintln!("error: --record {}: {e:#}", out.display());
            return ExitCode::from(BAD_INPUT);
        }
        if !quiet {
            let note = format!(
                "recording written to {0} (open it with `rerun {0}`)",
                out.display()
            );
            // Standard output may be carrying the JSON; a closed pipe is no error here.
            let _ = if json_to_stdout {
                writeln!(std::io::stderr(), "{note}")
            } else {
                writeln!(std::io::stdout(), "{note}")
            };
        }
    }
    ExitCode::SUCCESS
}

fn impact(which: ImpactKind, json: bool, plot: Option<PathBuf>, params: Vec<String>) -> ExitCode {
    let (setup, inc) = match which {
        ImpactKind::BallBall { incoming, cut } => (
            impact_cmd::Setup::BallBall {
                speed: incoming.speed,
                cut: cut.to_radians(),
            },
            incoming,
        ),
        ImpactKind::Cushion { incoming, angle } => (
            impact_cmd::Setup::Cushion {
                speed: incoming.speed,
                angle: angle.to_radians(),
            },
            incoming,
        ),
    };
    let req = impact_cmd::Request {
        setup,
        topspin: inc.topspin,
        sidespin: inc.sidespin,
        params,
        json,
        plot,
    };
    let (doc, samples, axes) = match impact_cmd::run(&req) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {e:#}");
            return ExitCode::from(BAD_INPUT);
        }
    };
    if req.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&doc).expect("finite numbers")
        );
    } else {
        print!("{}", impact_cmd::text(&doc));
    }
    if let Some(path) = &req.plot {
        if let Err(e) = impact_cmd::plot(&samples, axes, path) {
            eprintln!("error: --plot {}: {e:#}", path.display());
            return ExitCode::from(BAD_INPUT);
        }
        if !req.json {
            println!("plot written to {}", path.display());
        }
    }
    ExitCode::SUCCESS
}

fn validate(req: validate_cmd::Request) -> ExitCode {
    match validate_cmd::execute(&req) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(SIM_FAILED),
        Err(e) => {
            eprintln!("error: {}", e.0);
            ExitCode::from(BAD_INPUT)
        }
    }
}

fn synth(req: discrepancy_cmd::SynthRequest) -> ExitCode {
    match discrepancy_cmd::synth(&req) {
        Ok(text) => {
            print!("{text}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(BAD_INPUT)
        }
    }
}

fn discrepancy(req: discrepancy_cmd::Request, quiet: bool) -> ExitCode {
    let m = match discrepancy_cmd::load(&req) {
        Ok(m) => m,
        Err(e) => {
            eprintln!("error: {e:#}");
            return ExitCode::from(BAD_INPUT);
        }
    };
    if let Some(p) = &req.json
        && let Err(e) = output::check_output(p)
    {
        eprintln!("error: --json {}: {e}", p.display());
        return ExitCode::from(BAD_INPUT);
    }
    if let Some(d) = &req.report {
        // A file of that name, or a file on its way, is in the way of the report directory.
        let in_the_way = if d.exists() && !d.is_dir() {
            Err("is a file, not a directory".to_string())
        } else {
            output::check_output(&d.join("report.json"))
        };
        if let Err(e) = in_the_way {
            eprintln!("error: --report {}: {e}", d.display());
            return ExitCode::from(BAD_INPUT);
        }
    }
    let outcome = match discrepancy_cmd::run(&m) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {}: {e:#}", req.data.display());
            return ExitCode::from(SIM_FAILED);
        }
    };
    if !quiet {
        print!(
            "{}",
            snooker_validation::discrepancy::report::text(&m, &outcome)
        );
    }
    match discrepancy_cmd::write(&req, &m, &outcome) {
        Ok(files) => {
            if !quiet {
                for f in files {
                    println!("wrote {}", f.display());
                }
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(BAD_INPUT)
        }
    }
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { BAD_INPUT } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    match cli.command {
        Command::Simulate {
            scene,
            json,
            quiet,
            record,
            record_rate,
        } => simulate(
            scene,
            json,
            quiet,
            record.map(|p| (p, record::RecordOptions { rate: record_rate })),
        ),
        Command::Synth {
            scene,
            effects,
            params,
            fps,
            noise,
            seed,
            drop,
            duration,
            fit,
            out,
        } => synth(discrepancy_cmd::SynthRequest {
            scene,
            effects,
            params,
            camera: snooker_validation::discrepancy::synth::Camera {
                fps,
                noise: noise * 1e-3,
                drop_rate: drop,
                seed,
                max_duration: duration,
            },
            fit,
            out,
        }),
        Command::Discrepancy {
            data,
            model,
            report,
            json,
            quiet,
        } => discrepancy(
            discrepancy_cmd::Request {
                data,
                model,
                report,
                json,
            },
            quiet,
        ),
        Command::Impact {
            which,
            json,
            plot,
            params,
        } => impact(which, json, plot, params),
        Command::Validate {
            scenes,
            json,
            markdown,
            dt,
            convergence,
        } => validate(validate_cmd::Request {
            scenes,
            dt,
            convergence,
            json,
            markdown,
        }),
    }
}
