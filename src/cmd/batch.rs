//! `snooker batch`: many scenes on every core; their results as JSON lines or a Parquet table
//! of per-shot summaries (the `snooker-batch` crate).

use super::{FAILED, bad_input};
use crate::output::{self, AtomicFile};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use snooker_batch::{Outcome, Source, Summary, input, line, run_sources};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// Scenes simulated, and their results written, at a time: a batch of millions holds only
/// this many scenes and shots in memory.
const CHUNK: usize = 4096;

/// Arguments of `snooker batch`.
#[derive(clap::Args)]
pub struct Args {
    /// A directory of scene files (`*.toml`, in file-name order) or a JSON-lines file
    /// (`*.jsonl`: one scene object per line, with the scene file's keys).
    pub scenes: PathBuf,
    /// Where the results go: JSON lines (one result per scene, as `simulate --json` writes
    /// it, plus its `source`), or, for a name ending in `.parquet`, a table of per-shot
    /// summaries (the book's "Many shots" page, docs/python.md). Another extension than
    /// .jsonl, .ndjson, .json or .parquet (any case) is refused.
    #[arg(long, value_name = "RESULTS")]
    pub out: PathBuf,
    /// Threads to simulate on (default: every core; at most 1024).
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Print nothing but errors (no progress bar, no summary).
    #[arg(long, short)]
    pub quiet: bool,
}

/// How the results are written.
enum Writer {
    Lines(AtomicFile),
    Table(Vec<Summary>),
}

impl Writer {
    /// Writes the outcomes of `sources`, in order.
    fn add(&mut self, sources: &[Source], outcomes: &[Outcome]) -> anyhow::Result<()> {
        match self {
            Writer::Lines(file) => {
                let mut text = String::new();
                for (src, o) in sources.iter().zip(outcomes) {
                    let doc = line::outcome_line(&src.name, o);
                    text.push_str(&serde_json::to_string(&doc)?);
                    text.push('\n');
                }
                file.write(text.as_bytes())
            }
            Writer::Table(rows) => {
                let new = sources.iter().zip(outcomes);
                rows.extend(new.map(|(src, o)| Summary::of_outcome(&src.name, o)));
                Ok(())
            }
        }
    }

    /// Puts the results file in place.
    fn finish(self, path: &Path) -> anyhow::Result<()> {
        match self {
            Writer::Lines(file) => file.commit(),
            Writer::Table(rows) => {
                output::write_atomic(path, &snooker_batch::table::parquet_bytes(&rows)?)
            }
        }
    }
}

/// A progress bar with shots/s on standard error (hidden when quiet or not a terminal).
fn progress(len: usize, quiet: bool) -> ProgressBar {
    let bar = ProgressBar::new(len as u64);
    if quiet {
        bar.set_draw_target(ProgressDrawTarget::hidden());
    }
    if let Ok(style) = ProgressStyle::with_template(
        "{bar:40} {pos}/{len} shots, {per_sec} ({elapsed}, {eta} left)",
    ) {
        bar.set_style(style);
    }
    bar
}

/// Runs the command.
pub fn run(args: Args) -> ExitCode {
    let out = &args.out;
    if let Err(e) = output::check_output(out) {
        return bad_input(format!("--out {}: {e}", out.display()));
    }
    // A name asking for a format the batch does not write would get JSON lines under it.
    if let Some(x) = out
        .extension()
        .map(|x| x.to_string_lossy().to_ascii_lowercase())
        && !["jsonl", "ndjson", "json", "parquet"].contains(&x.as_str())
    {
        return bad_input(format!(
            "--out {}: the results are JSON lines (.jsonl, .ndjson, .json) or a Parquet table \
             (.parquet), not .{x}",
            out.display()
        ));
    }
    if output::same_file(out, &args.scenes) {
        return bad_input(format!(
            "--out {}: is the batch's input (the results would replace its scenes)",
            out.display()
        ));
    }
    if let Some(n) = args.threads
        && let Err(e) = snooker_batch::run::check_threads(n)
    {
        return bad_input(format!("--threads {n}: {}", e.reason));
    }
    let sources = match input::read(&args.scenes) {
        Ok(s) => s,
        Err(e) => return bad_input(e),
    };
    let table = out
        .extension()
        .is_some_and(|x| x.eq_ignore_ascii_case("parquet"));
    let mut writer = if table {
        Writer::Table(Vec::with_capacity(sources.len()))
    } else {
        match AtomicFile::create(out) {
            Ok(f) => Writer::Lines(f),
            Err(e) => return bad_input(format!("--out {}: {e:#}", out.display())),
        }
    };
    let bar = progress(sources.len(), args.quiet);
    let start = Instant::now();
    let mut failed = Vec::new();
    for chunk in sources.chunks(CHUNK) {
        let outcomes = match run_sources(chunk, args.threads, || bar.inc(1)) {
            Ok(o) => o,
            Err(e) => return bad_input(format!("--threads: {e}")),
        };
        for (src, o) in chunk.iter().zip(&outcomes) {
            if let Some(e) = o.error() {
                failed.push((src.name.clone(), e));
            }
        }
        if let Err(e) = writer.add(chunk, &outcomes) {
            return bad_input(format!("--out {}: {e:#}", out.display()));
        }
    }
    bar.finish_and_clear();
    let wall = start.elapsed().as_secs_f64();
    if let Err(e) = writer.finish(out) {
        return bad_input(format!("--out {}: {e:#}", out.display()));
    }
    for (source, e) in failed.iter().take(10) {
        // A scene's own errors name it already; a simulation's do not.
        if e.starts_with(source.as_str()) {
            eprintln!("error: {e}");
        } else {
            eprintln!("error: {source}: {e}");
        }
    }
    if failed.len() > 10 {
        eprintln!(
            "error: ... and {} more (each in its row)",
            failed.len() - 10
        );
    }
    if !args.quiet {
        let n = sources.len();
        outln!(
            "{n} scenes, {} failed, in {wall:.2} s ({:.0} shots/s); results written to {}",
            failed.len(),
            n as f64 / wall,
            out.display()
        );
    }
    if failed.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(FAILED)
    }
}
