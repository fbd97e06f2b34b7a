//! The cross-check report: what one `snooker validate` produces ([`Report`], serialised as the
//! JSON document), and its renderers: the terminal table ([`text`]) and the Markdown document
//! docs/validation.md ([`markdown`], with its prose in the private module `method`).

mod markdown;
mod method;
mod text;

pub use markdown::markdown;
pub use method::METHOD;
pub use text::text;

use crate::compare::{Comparison, Figure, FigureKind};
use crate::convergence::StepRow;
use crate::crosscheck::{RunReport, Verdict};
use crate::nose::NoseRebound;
use crate::stretch::Stretch;
use serde::Serialize;

/// Everything one `snooker validate` produces.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// rapier's time step, s.
    pub dt: f64,
    /// One per (scene, models) run.
    pub runs: Vec<RunReport>,
    /// rapier's cushion rebound with the nose at 7R/5, frictionless (when measured).
    pub nose: Vec<NoseRebound>,
    /// The time-step study (when run).
    pub convergence: Vec<StepRow>,
}

/// How many runs had each verdict.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// Runs compared (passed or failed).
    pub compared: usize,
    /// Runs compared and passed.
    pub passed: usize,
    /// Runs failed (compared and failed, or our engine failed).
    pub failed: usize,
    /// Runs skipped.
    pub skipped: usize,
}

impl Report {
    /// True when no run failed.
    pub fn pass(&self) -> bool {
        self.runs.iter().all(RunReport::pass)
    }

    /// Runs compared, passed, failed and skipped.
    pub fn counts(&self) -> Counts {
        let mut c = Counts::default();
        for r in &self.runs {
            match r.verdict() {
                Verdict::Pass => {
                    c.compared += 1;
                    c.passed += 1;
                }
                Verdict::Fail => {
                    c.compared += 1;
                    c.failed += 1;
                }
                Verdict::Skip => c.skipped += 1,
                Verdict::Error => c.failed += 1,
            }
        }
        c
    }
}

/// "n same" or "DIFFER (ours n, rapier m)" for the compared impacts.
fn sequence_cell(c: &Comparison) -> String {
    let n = c.compared;
    if c.sequence_match {
        format!("{n} same")
    } else {
        format!("DIFFER (ours {n}, rapier {})", c.rapier.len())
    }
}

/// "n stretches, all same" or "n stretches, k differ".
fn stretches_cell(stretches: &[Stretch]) -> String {
    let differ = stretches
        .iter()
        .filter(|s| !s.comparison.sequence_match)
        .count();
    if differ == 0 {
        format!("{} same", stretches.len())
    } else {
        format!("{} of {} DIFFER", differ, stretches.len())
    }
}

/// The worst figure of a kind over several comparisons (largest ratio to its tolerance).
fn worst_of<'a>(
    cs: impl IntoIterator<Item = &'a Comparison>,
    kind: FigureKind,
) -> Option<&'a Figure> {
    cs.into_iter()
        .filter_map(|c| c.figure(kind))
        .max_by(|a, b| a.ratio().total_cmp(&b.ratio()))
}

/// The compact "diff / tol" of a figure, or "-" when there is none.
fn figure_cell(f: Option<&Figure>) -> String {
    match f {
        Some(f) => format!(
            "{} / {}{}",
            sci(f.diff),
            sci(f.tol),
            if f.pass() { "" } else { " **FAIL**" }
        ),
        None => "-".into(),
    }
}

/// A number in short scientific notation.
pub fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if x.is_infinite() {
        "inf".into()
    } else {
        format!("{x:.2e}")
    }
}

/// The whole-shot comparison as information: "same, within", "same, beyond", "differs".
fn information_cell(c: &Comparison) -> &'static str {
    match (c.sequence_match, c.figures.iter().all(Figure::pass)) {
        (true, true) => "same sequence, within",
        (true, false) => "same sequence, beyond",
        (false, _) => "sequence differs",
    }
}
