//! The time-step study: the scene set in the frictionless limit at halving time steps, with the
//! largest difference between the engines of each figure. The step is chosen where these
//! settle (stop shrinking as dt halves): what is left is the soft contact's share.

use crate::crosscheck::{Outcome, RunReport, SceneSpec, check};
use crate::scenes::ImpactModels;
use serde::Serialize;
use std::time::Instant;

/// The figures in the study, in column order.
pub const FIGURES: [&str; 6] = [
    "impact time",
    "velocity after impact",
    "spin after impact",
    "slide-to-roll time",
    "slide-to-roll speed",
    "final position",
];

/// One time step of the study.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StepRow {
    /// rapier's time step, s.
    pub dt: f64,
    /// Per figure of [`FIGURES`]: the largest difference over the scenes.
    pub max_diff: Vec<f64>,
    /// Runs whose verdict passed, out of `runs`.
    pub passed: usize,
    /// Runs compared.
    pub runs: usize,
    /// Wall-clock seconds for the whole set.
    pub seconds: f64,
}

/// The largest difference of each figure of [`FIGURES`] over `runs`.
pub fn max_diffs(runs: &[RunReport]) -> Vec<f64> {
    FIGURES
        .iter()
        .map(|name| {
            runs.iter()
                .filter_map(|r| match &r.outcome {
                    Outcome::Compared { comparison, .. } => Some(comparison),
                    _ => None,
                })
                .flat_map(|c| c.figures.iter().filter(|f| f.name == *name))
                .map(|f| f.diff)
                .fold(0.0, f64::max)
        })
        .collect()
}

/// Runs the study over `specs` at each of `dts`; `tick` is called after each run.
pub fn study(specs: &[SceneSpec], dts: &[f64], mut tick: impl FnMut(&RunReport)) -> Vec<StepRow> {
    dts.iter()
        .map(|&dt| {
            let start = Instant::now();
            let runs: Vec<RunReport> = specs
                .iter()
                .map(|s| {
                    let r = check(s, ImpactModels::Frictionless, dt);
                    tick(&r);
                    r
                })
                .collect();
            StepRow {
                dt,
                max_diff: max_diffs(&runs),
                passed: runs.iter().filter(|r| r.pass()).count(),
                runs: runs.len(),
                seconds: start.elapsed().as_secs_f64(),
            }
        })
        .collect()
}
