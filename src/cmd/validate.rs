//! `snooker validate`: the cross-check against rapier over the validation scene set (or given
//! scenes), with a progress bar, a report table, and optional JSON and Markdown output.

use indicatif::{ProgressBar, ProgressStyle};
use snooker_validation::convergence;
use snooker_validation::crosscheck::{self, RunReport, SceneSpec};
use snooker_validation::nose;
use snooker_validation::report::{self, Report};
use snooker_validation::scenes::BUILTIN;
use std::path::{Path, PathBuf};

/// The finest rapier time step `--dt` takes, s: 10^5 steps a simulated second (1e-300 was
/// taken, and the cross-check never finished).
pub const MIN_DT: f64 = 1e-5;

/// Time steps of the convergence study, s (halving).
pub const STUDY_STEPS: [f64; 5] = [4e-4, 2e-4, 1e-4, 5e-5, 2.5e-5];

/// Arguments of `snooker validate`: the cross-check against rapier on the validation scenes
/// (or the given ones).
#[derive(clap::Args)]
pub struct Args {
    /// A scene file to check (repeatable); the built-in validation set when none is given.
    #[arg(long = "scene", value_name = "S")]
    pub scenes: Vec<PathBuf>,
    /// Write the report as JSON to this file.
    #[arg(long, value_name = "OUT")]
    pub json: Option<PathBuf>,
    /// Write the report as Markdown to this file (docs/validation.md).
    #[arg(long, value_name = "OUT")]
    pub markdown: Option<PathBuf>,
    /// rapier's time step, s.
    #[arg(long, default_value_t = crosscheck::DEFAULT_DT)]
    pub dt: f64,
    /// Also run the time-step study (several minutes).
    #[arg(long)]
    pub convergence: bool,
}

/// Why `snooker validate` stopped before comparing, or could not write its report.
#[derive(Debug, thiserror::Error)]
pub enum BadInput {
    /// The time step is not in (0, 0.01] s.
    #[error(
        "--dt {}: must be a time step in [1e-5, 0.01] s (a finer one takes rapier hours \
         for a shot of seconds; the time-step study's finest is 2.5e-5 s)",
        snooker_engine::shown::Shown(*.0)
    )]
    Dt(f64),
    /// A scene file is not valid.
    #[error(transparent)]
    Scene(#[from] snooker_scene::SceneError),
    /// The report could not be encoded as JSON.
    #[error("the report as JSON: {0}")]
    Json(#[from] serde_json::Error),
    /// An output path cannot become a file, is another output's, or is an input (checked
    /// before the run).
    #[error("{0}")]
    Output(String),
    /// An output file could not be written (nothing was: the outputs are put in place
    /// together).
    #[error("{0}")]
    Write(String),
}

/// Loads the requested scenes (or the built-in set).
pub fn load_scenes(paths: &[PathBuf]) -> Result<Vec<SceneSpec>, BadInput> {
    let parsed: Result<Vec<snooker_scene::Scene>, snooker_scene::SceneError> = if paths.is_empty() {
        BUILTIN
            .iter()
            .map(|(file, text)| snooker_scene::parse(text, &format!("validation/scenes/{file}")))
            .collect()
    } else {
        paths.iter().map(|p| snooker_scene::load(p)).collect()
    };
    Ok(parsed?
        .into_iter()
        .map(|s| SceneSpec {
            name: s.name,
            setup: s.setup,
            options: s.options,
        })
        .collect())
}

fn bar(len: usize) -> ProgressBar {
    let pb = ProgressBar::new(len as u64);
    if let Ok(style) =
        ProgressStyle::with_template("{prefix:>10} [{bar:30}] {pos}/{len} {wide_msg}")
    {
        pb.set_style(style.progress_chars("=> "));
    }
    pb
}

/// Runs the cross-check; returns the report.
pub fn run(args: &Args, specs: &[SceneSpec]) -> Report {
    let pb = bar(specs.len());
    pb.set_prefix("cross-check");
    let mut runs = Vec::new();
    for s in specs {
        pb.set_message(s.name.clone());
        runs.extend(crosscheck::check_scene(s, args.dt));
        pb.inc(1);
    }
    pb.finish_and_clear();
    let with_cushions: Vec<&SceneSpec> = specs
        .iter()
        .filter(|s| {
            runs.iter()
                .filter(|r| r.scene == s.name)
                .filter_map(RunReport::compared)
                .any(|c| c.whole.ours.iter().any(|p| p.is_cushion()))
        })
        .collect();
    let pb = bar(with_cushions.len());
    pb.set_prefix("nose");
    let nose = with_cushions
        .iter()
        .filter_map(|s| {
            pb.set_message(s.name.clone());
            let n = nose::nose_rebound(s, args.dt);
            pb.inc(1);
            n
        })
        .collect();
    pb.finish_and_clear();
    let convergence = if args.convergence {
        let pb = bar(specs.len() * STUDY_STEPS.len());
        pb.set_prefix("dt study");
        let rows = convergence::study(specs, &STUDY_STEPS, |r| {
            pb.set_message(r.scene.clone());
            pb.inc(1);
        });
        pb.finish_and_clear();
        rows
    } else {
        Vec::new()
    };
    Report {
        dt: args.dt,
        runs,
        nose,
        convergence,
    }
}

/// Whether `--json` asks for standard output (`-`, as `simulate`, `referee` and `plan` take it).
fn json_to_stdout(args: &Args) -> bool {
    args.json.as_ref().is_some_and(|p| p.as_os_str() == "-")
}

/// Prints the report and writes the requested files, all or none; with `--json -` the JSON
/// is standard output's and the text report goes to standard error.
pub fn output(args: &Args, report: &Report) -> Result<(), BadInput> {
    let to_stdout = json_to_stdout(args);
    let say = |text: &str| {
        if to_stdout {
            eprint!("{text}");
        } else {
            out!("{text}");
        }
    };
    say(&report::text(report));
    let mut files = crate::output::Outputs::default();
    let json = match &args.json {
        Some(_) => Some(serde_json::to_string_pretty(report)? + "\n"),
        None => None,
    };
    if let (Some(p), Some(text)) = (&args.json, &json)
        && !to_stdout
    {
        files.add("--json", p, text.as_bytes());
    }
    if let Some(p) = &args.markdown {
        files.add("--markdown", p, report::markdown(report).as_bytes());
    }
    files.commit().map_err(BadInput::Write)?;
    if let (Some(p), Some(text)) = (&args.json, &json) {
        if to_stdout {
            out!("{text}");
        } else {
            say(&format!("JSON written to {}\n", p.display()));
        }
    }
    if let Some(p) = &args.markdown {
        say(&format!("Markdown written to {}\n", p.display()));
    }
    Ok(())
}

/// Checks, before the cross-check's minutes, that `--json` and `--markdown` can be written,
/// are not one file, and are not a scene checked.
fn check_outputs(args: &Args) -> Result<(), BadInput> {
    let json = args.json.clone().filter(|_| !json_to_stdout(args));
    let inputs: Vec<&Path> = args.scenes.iter().map(PathBuf::as_path).collect();
    crate::output::check_outputs(
        &[("--json", json), ("--markdown", args.markdown.clone())],
        &inputs,
    )
    .map_err(BadInput::Output)
}

/// Runs the command: exit 0 when every verdict passed, 1 when one failed, 2 for bad input or
/// an output that could not be written.
pub fn run_command(args: Args) -> std::process::ExitCode {
    match execute(&args) {
        Ok(true) => std::process::ExitCode::SUCCESS,
        Ok(false) => std::process::ExitCode::from(super::FAILED),
        Err(e) => super::bad_input(e),
    }
}

/// Checks the arguments, runs the cross-check and writes the outputs: `Ok(true)` when every
/// verdict passed, `Ok(false)` when one failed, `Err` for bad input or an output that could
/// not be written.
pub fn execute(args: &Args) -> Result<bool, BadInput> {
    if !(args.dt.is_finite() && args.dt >= MIN_DT && args.dt <= 1e-2) {
        return Err(BadInput::Dt(args.dt));
    }
    check_outputs(args)?;
    let specs = load_scenes(&args.scenes)?;
    let report = run(args, &specs);
    output(args, &report)?;
    Ok(report.pass())
}
