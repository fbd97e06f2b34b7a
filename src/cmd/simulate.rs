//! `snooker simulate`: one scene through the engine; a summary, the JSON result and a Rerun
//! recording.

use super::{bad_input, failed};
use crate::{output, record};
use snooker_engine::shown::Shown;
use snooker_scene::{self as scene, result};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Arguments of `snooker simulate`.
#[derive(clap::Args)]
pub struct Args {
    /// Scene file (TOML); the format is the book's "File formats" page (docs/formats.md).
    pub scene: Option<PathBuf>,
    /// Write the result as JSON to this file, or to standard output with `-`.
    #[arg(long, value_name = "OUT")]
    pub json: Option<String>,
    /// Print nothing but errors (and the JSON if it goes to standard output).
    #[arg(long, short)]
    pub quiet: bool,
    /// Write a Rerun recording of the shot to this file (open it with `rerun OUT.rrd`,
    /// viewer `pip install rerun-sdk==0.36.3`; see docs/recording.md).
    #[arg(long, value_name = "OUT.rrd")]
    pub record: Option<PathBuf>,
    /// Sample rate of the recording, Hz (every event instant is sampled as well).
    #[arg(long, value_name = "HZ", default_value_t = record::DEFAULT_RATE, requires = "record")]
    pub record_rate: f64,
}

/// Runs the command.
pub fn run(args: Args) -> ExitCode {
    let loaded = match &args.scene {
        Some(p) => scene::load(p),
        None => scene::parse(scene::DEFAULT_SCENE, scene::DEFAULT_SCENE_FILE),
    };
    let scene = match loaded {
        Ok(s) => s,
        Err(e) => return bad_input(e),
    };
    let json = args.json.as_deref();
    let outputs = [
        ("--json", json.filter(|o| *o != "-").map(PathBuf::from)),
        ("--record", args.record.clone()),
    ];
    let inputs: Vec<&Path> = args.scene.iter().map(PathBuf::as_path).collect();
    if let Err(e) = output::check_outputs(&outputs, &inputs) {
        return bad_input(e);
    }
    let recording = args.record.map(|p| {
        (
            p,
            record::RecordOptions {
                rate: args.record_rate,
                ..Default::default()
            },
        )
    });
    if let Some((_, opts)) = &recording
        && let Err(e) = opts.validate()
    {
        return bad_input(format!("--record-rate {}: {e}", Shown(opts.rate)));
    }
    let shot = match snooker_engine::simulate(&scene.setup, &scene.options) {
        Ok(s) => s,
        Err(e) => {
            let file = args
                .scene
                .as_deref()
                .map_or(scene::DEFAULT_SCENE_FILE.into(), |p| {
                    p.display().to_string()
                });
            return failed(format!("{file}: {e}"));
        }
    };
    let json_to_stdout = json == Some("-");
    if !args.quiet {
        let text = result::summary(&scene, &shot);
        if json_to_stdout {
            eprint!("{text}");
        } else {
            out!("{text}");
        }
    }
    // The recording is made before anything is written, so that a failure leaves no result.
    let recording = match recording {
        None => None,
        Some((out, opts)) => match record::encode(&scene, &shot, &opts) {
            Ok(bytes) => Some((out, bytes)),
            Err(e @ (record::RecordError::Rate(_) | record::RecordError::TooLarge(_))) => {
                return bad_input(format!("--record {}: {e}", out.display()));
            }
            Err(e) => return failed(format!("--record {}: {e}", out.display())),
        },
    };
    let text = json.map(|_| {
        let doc = result::result_record(&scene, &shot);
        serde_json::to_string_pretty(&doc).expect("JSON of finite numbers")
    });
    // Every file staged whole before any is put in place (output::Outputs).
    let mut files = output::Outputs::default();
    files.add_json(json, text.as_ref());
    if let Some((out, bytes)) = &recording {
        files.add("--record", out, bytes);
    }
    if let Err(e) = files.commit() {
        return bad_input(e);
    }
    match (json, text) {
        (Some("-"), Some(text)) => {
            let mut stdout = std::io::stdout().lock();
            if writeln!(stdout, "{text}").is_err() {
                return ExitCode::from(super::FAILED);
            }
        }
        (Some(out), Some(_)) if !args.quiet => outln!("result written to {out}"),
        _ => {}
    }
    if let Some((out, _)) = &recording {
        super::say_recording_written(out, args.quiet, json_to_stdout);
    }
    ExitCode::SUCCESS
}
