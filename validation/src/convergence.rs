//! The time-step study: the scene set in the frictionless limit at halving time steps, with the
//! largest difference between the engines of each figure. The step is chosen where these
//! settle (stop shrinking as dt halves): what is left is the soft contact's share.

use crate::compare::FigureKind;
use crate::crosscheck::{Method, RunReport, SceneSpec, check};
use crate::scenes::ImpactModels;
use serde::Serialize;
use std::time::Instant;

/// The figures in the study, in column order.
pub const FIGURES: [FigureKind; 6] = [
    FigureKind::ImpactTime,
    FigureKind::VelocityAfter,
    FigureKind::SpinAfter,
    FigureKind::RollTime,
    FigureKind::RollSpeed,
    FigureKind::FinalPosition,
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

/// The largest difference of each figure of [`FIGURES`] over the runs of `runs` compared
/// over the whole shot (a run compared stretch by stretch has by-design differences, landings,
/// that do not shrink with the step).
pub fn max_diffs(runs: &[RunReport]) -> Vec<f64> {
    FIGURES
        .iter()
        .map(|&kind| {
            runs.iter()
                .filter_map(RunReport::compared)
                .filter(|c| c.method == Method::WholeShot)
                .filter_map(|c| c.whole.figure(kind))
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
