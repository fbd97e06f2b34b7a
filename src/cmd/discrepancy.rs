//! `snooker discrepancy`: the workflow on measured data (find where simulation and measurement
//! disagree, name the missing effects, add them, show the gap shrink), with its report, plots
//! and Rerun overlays.

use super::{bad_input, failed};
use crate::output::{Outputs, check_output_dir, check_outputs};
use crate::{plot, record};
use anyhow::Context;
use snooker_discrepancy::{self as dsc, Findings, Measurement, data_file};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Arguments of `snooker discrepancy`.
#[derive(clap::Args)]
pub struct Args {
    /// The measured data file (TOML; docs/discrepancy.md).
    data: PathBuf,
    /// A model file ([params] and [models] as in a scene) to start from instead of the
    /// scenes' own model.
    #[arg(long, value_name = "FILE")]
    model: Option<PathBuf>,
    /// Write the full report (JSON, summary, plots) into this directory.
    #[arg(long, value_name = "DIR")]
    report: Option<PathBuf>,
    /// Write the JSON report to this file (`-`: standard output, the summary then on
    /// standard error).
    #[arg(long, value_name = "OUT")]
    json: Option<PathBuf>,
    /// Instead of the workflow: cross-validate on the shots whose names start with PREFIX
    /// (the other shots always train): the thesis's model, the start model, the rigid model
    /// with e_ball and mu_ball fitted, and the workflow, each fitted on one half and tested
    /// on the other. With --report, writes cross-validation.md and .json there.
    #[arg(long, value_name = "PREFIX")]
    cross_validate: Option<String>,
    /// Print nothing but errors.
    #[arg(long, short)]
    quiet: bool,
}

/// Runs the command.
pub fn run(args: Args) -> ExitCode {
    let m = match data_file::load(&args.data, args.model.as_deref()) {
        Ok(m) => m,
        Err(e) => return bad_input(e),
    };
    if let (Some(p), Some(_)) = (&args.json, &args.cross_validate) {
        return bad_input(format!(
            "--json {}: --cross-validate writes no discrepancy report; its results go to \
             --report DIR (cross-validation.json and .md)",
            p.display()
        ));
    }
    let mut outputs = vec![("--json", args.json.clone().filter(|p| !is_stdout(p)))];
    if let Some(d) = &args.report {
        // A file of that name, or a file on its way, is in the way of the report directory.
        for file in report_files(&m, args.cross_validate.is_some()) {
            if let Err(e) = check_output_dir(d, &file) {
                return bad_input(format!("--report {}: {file}: {e}", d.display()));
            }
            outputs.push(("--report", Some(d.join(file))));
        }
    }
    // No output may replace another, nor a file the run reads (the data file, what it names,
    // the model file).
    let mut inputs = data_file::files(&args.data);
    inputs.extend(args.model.clone());
    let inputs: Vec<&Path> = inputs.iter().map(PathBuf::as_path).collect();
    if let Err(e) = check_outputs(&outputs, &inputs) {
        return bad_input(e);
    }
    if let Some(prefix) = &args.cross_validate {
        return cross_validation(&args, &m, prefix);
    }
    let findings = match dsc::run(&m, &dsc::Options::default()) {
        Ok(o) => o,
        // Too few measured values for what `fit` asks: the data's fault, not the run's.
        Err(snooker_discrepancy::DiscrepancyError::TooFewResiduals {
            residuals,
            unknowns,
        }) => {
            return bad_input(format!(
                "{}: key `fit`: the measurements give {residuals} residuals, fewer than the \
                 {unknowns} unknowns fitted (a track of too few samples?)",
                args.data.display()
            ));
        }
        Err(e) => return failed(format!("{}: {e}", args.data.display())),
    };
    // With the JSON on standard output, the summary goes to standard error.
    let to_stdout = args.json.as_deref().is_some_and(is_stdout);
    let say = |text: &str| match (args.quiet, to_stdout) {
        (true, _) => {}
        (false, true) => eprint!("{text}"),
        (false, false) => out!("{text}"),
    };
    say(&dsc::report::text(&m, &findings));
    match write(&args, &m, &findings) {
        Ok(files) => {
            for f in files {
                say(&format!("wrote {}\n", f.display()));
            }
            ExitCode::SUCCESS
        }
        Err(e) => bad_input(format!("{e:#}")),
    }
}

/// The files the report directory gets: the cross-validation's two, or the report, its
/// summary, the plots of what was measured and an overlay per tracked shot.
pub fn report_files(m: &Measurement, cross_validation: bool) -> Vec<String> {
    if cross_validation {
        return vec!["cross-validation.md".into(), "cross-validation.json".into()];
    }
    let mut files = vec!["report.json".to_string(), "summary.txt".to_string()];
    if m.shots.iter().any(|s| !s.samples.is_empty()) {
        files.extend(["tracks.png".into(), "residuals.png".into()]);
    }
    if m.shots.iter().any(|s| !s.observables.is_empty()) {
        files.push("observables.png".into());
    }
    let tracked = (0..m.shots.len()).filter(|&i| !m.shots[i].samples.is_empty());
    files.extend(tracked.map(|i| overlay_file(m, i)));
    files
}

/// Whether an output path is `-`, standard output.
fn is_stdout(p: &Path) -> bool {
    p.as_os_str() == "-"
}

/// Writes the JSON report and the report directory, all or none ([`Outputs`]).
fn write(req: &Args, m: &Measurement, o: &Findings) -> anyhow::Result<Vec<PathBuf>> {
    let doc = dsc::report::json(m, o);
    let text = serde_json::to_string_pretty(&doc)? + "\n";
    let mut files = Outputs::default();
    let mut written = Vec::new();
    let mut add = |flag: &str, p: PathBuf, bytes: &[u8]| {
        files.add(flag, &p, bytes);
        written.push(p);
    };
    if let Some(p) = req.json.as_ref().filter(|p| !is_stdout(p)) {
        add("--json", p.clone(), text.as_bytes());
    }
    if let Some(dir) = &req.report {
        add("--report", dir.join("report.json"), text.as_bytes());
        let summary = dsc::report::text(m, o);
        add("--report", dir.join("summary.txt"), summary.as_bytes());
        if m.shots.iter().any(|s| !s.samples.is_empty()) {
            let png = plot::png_bytes(|p| plot::tracks(m, &o.baseline.sims, &o.last.sims, p))?;
            add("--report", dir.join("tracks.png"), &png);
            let png = plot::png_bytes(|p| plot::residuals(m, &o.baseline.sims, &o.last.sims, p))?;
            add("--report", dir.join("residuals.png"), &png);
        }
        if m.shots.iter().any(|s| !s.observables.is_empty()) {
            let png = plot::png_bytes(|p| plot::observables(o, p))?;
            add("--report", dir.join("observables.png"), &png);
        }
        for (p, bytes) in overlays(m, o, dir)? {
            add("--report", p, &bytes);
        }
    }
    files.commit().map_err(anyhow::Error::msg)?;
    if req.json.as_deref().is_some_and(is_stdout) {
        out!("{text}");
    }
    Ok(written)
}

/// Colour of the measured centroids in the overlay recordings.
pub const MEASURED_COLOR: [u8; 3] = [255, 0, 255];
/// Colour of the start model's ball centres in the overlay recordings.
pub const START_MODEL_COLOR: [u8; 3] = [255, 150, 0];

/// The overlay recording's file name for shot `index` of `m`: `overlay.rrd` for a single
/// shot, else `overlay-<index>-<name>.rrd` with the name reduced to safe characters.
pub fn overlay_file(m: &Measurement, index: usize) -> String {
    if m.shots.len() == 1 {
        return "overlay.rrd".into();
    }
    let name: String = m.shots[index]
        .name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' {
                c
            } else {
                '_'
            }
        })
        .take(40)
        .collect();
    format!("overlay-{index}-{name}.rrd")
}

/// One Rerun recording per tracked shot, with its path: the final model's shot as balls,
/// with the measured centroids (`measured/<ball>`) and the start model's centres at the same
/// times (`start_model/<ball>`) as points on the cloth.
fn overlays(m: &Measurement, o: &Findings, dir: &Path) -> anyhow::Result<Vec<(PathBuf, Vec<u8>)>> {
    let mut written = Vec::new();
    for (i, shot) in m.shots.iter().enumerate() {
        if shot.samples.is_empty() {
            continue;
        }
        let (start, last) = (&o.baseline.sims[i], &o.last.sims[i]);
        let r = m.model.params.ball_radius;
        let mut overlays = Vec::new();
        for (b, id) in shot.ids().into_iter().enumerate() {
            let seen: Vec<_> = shot.samples.iter().filter(|s| s.ball == b).collect();
            if seen.is_empty() {
                continue;
            }
            let at_z = |x: f64, y: f64| snooker_engine::Vec3::new(x, y, r);
            overlays.push(record::Overlay {
                entity: vec!["measured".into(), id.clone()],
                points: seen
                    .iter()
                    .map(|s| (s.t, at_z(s.pos[0], s.pos[1])))
                    .collect(),
                color: MEASURED_COLOR,
                radius: 0.008,
            });
            overlays.push(record::Overlay {
                entity: vec!["start_model".into(), id],
                points: seen
                    .iter()
                    .map(|s| (s.t, start.tracks[b].state_at(s.t, &start.params).pos))
                    .collect(),
                color: START_MODEL_COLOR,
                radius: 0.006,
            });
        }
        let view = snooker_scene::Scene {
            name: format!("{} (final model)", shot.name),
            setup: shot.setup.clone(),
            options: snooker_engine::SimOptions::default(),
            strike: None,
        };
        let bytes =
            record::encode_with_overlays(&view, last, &record::RecordOptions::default(), &overlays)
                .with_context(|| format!("overlay recording of shot {}", shot.name))?;
        written.push((dir.join(overlay_file(m, i)), bytes));
    }
    Ok(written)
}

/// `--cross-validate PREFIX`: the fidelity table of train and test errors.
fn cross_validation(args: &Args, m: &Measurement, prefix: &str) -> ExitCode {
    use dsc::crossval::{Fitting, cross_validate};
    use snooker_engine::{Models, Params};
    let pool: Vec<usize> = (0..m.shots.len())
        .filter(|&i| m.shots[i].name.starts_with(prefix))
        .collect();
    if pool.len() < 2 {
        return bad_input(format!(
            "--cross-validate {prefix}: {} shot(s) of {} start with it; two at least are needed",
            pool.len(),
            args.data.display()
        ));
    }
    let thesis = dsc::Model {
        params: Params::default(),
        models: Models::default(),
    };
    let fittings = [
        (
            "thesis model (e_ball 0.89, mu_ball 0.05)",
            Fitting::Fixed(thesis),
        ),
        ("start model", Fitting::Fixed(m.model)),
        (
            "rigid model, e_ball and mu_ball fitted",
            Fitting::Effects(
                thesis,
                vec![dsc::Effect::BallRestitution, dsc::Effect::BallFriction],
            ),
        ),
        (
            "the workflow from the start model",
            Fitting::Workflow(m.model),
        ),
    ];
    let mut rows = Vec::new();
    for (name, f) in &fittings {
        match cross_validate(m, &pool, name, f) {
            Ok(r) => rows.push(r),
            Err(e) => return failed(format!("{}: {name}: {e}", args.data.display())),
        }
    }
    let mut md =
        String::from("| model | fitted on | train error | test error |\n|---|---|---|---|\n");
    for r in &rows {
        let fitted: Vec<String> = r
            .folds
            .iter()
            .map(|f| {
                let vals: Vec<String> = f
                    .fitted
                    .iter()
                    .flat_map(|x| {
                        x.params
                            .iter()
                            .zip(&x.values)
                            .map(|(p, v)| format!("{} {v:.3}", p.name))
                    })
                    .collect();
                if vals.is_empty() {
                    "-".to_string()
                } else {
                    format!("{}: {}", f.train.join("+"), vals.join(", "))
                }
            })
            .collect();
        md += &format!(
            "| {} | {} | {:.2} % | {:.2} % |\n",
            r.name,
            fitted.join("; "),
            100.0 * r.train_error,
            100.0 * r.test_error
        );
    }
    if !args.quiet {
        out!("{md}");
    }
    if let Some(dir) = &args.report {
        let json = match serde_json::to_string_pretty(&rows) {
            Ok(t) => t + "\n",
            Err(e) => return failed(format!("the cross-validation as JSON: {e}")),
        };
        let mut files = Outputs::default();
        files.add("--report", &dir.join("cross-validation.md"), md.as_bytes());
        files.add(
            "--report",
            &dir.join("cross-validation.json"),
            json.as_bytes(),
        );
        if let Err(e) = files.commit() {
            return bad_input(e);
        }
    }
    ExitCode::SUCCESS
}
