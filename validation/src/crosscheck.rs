//! One cross-check run: a scene with a choice of impact models, simulated by both engines,
//! reduced to records and compared against the derived tolerances.

use crate::compare::{Comparison, Scope, compare};
use crate::ensemble::{HALF_WIDTH, HEADING_STEP, Stat, StatRow, stats, summarise, turned};
use crate::rapier_run::{self, RapierRun};
use crate::rapier_world::{ImpactFriction, WorldConfig};
use crate::record::Record;
use crate::scenes::ImpactModels;
use crate::shapes::{CushionContact, jaw_solid};
use crate::tolerance::{Budget, allowances};
use serde::Serialize;
use snooker_engine::{Setup, SimOptions, simulate};
use std::time::Instant;

/// rapier's time step chosen by the convergence study (docs/validation.md), s.
pub const DEFAULT_DT: f64 = 1e-4;

/// Extra simulated time rapier is given beyond our engine's shot before it counts as not
/// stopping, s.
const EXTRA_TIME: f64 = 5.0;

/// Impacts closing slower than this are resting contacts, not compared, m/s: twice our
/// engine's micro-collision speed [`snooker_engine::impact::MIN_SEPARATION`].
pub const RESTING_APPROACH: f64 = 2.0 * snooker_engine::impact::MIN_SEPARATION;

/// A scene to check.
#[derive(Clone, Debug)]
pub struct SceneSpec {
    /// Its name.
    pub name: String,
    /// What both engines start from (the impact models are replaced per run).
    pub setup: Setup,
    /// Our engine's limits.
    pub options: SimOptions,
}

/// How a run went.
#[derive(Clone, Debug, Serialize)]
#[serde(rename_all = "snake_case", tag = "status")]
pub enum Outcome {
    /// Both engines ran and were compared.
    Compared {
        /// The comparison.
        comparison: Comparison,
        /// Depth the balls sank into rapier's cloth, m.
        sink: f64,
        /// rapier's time step, s.
        dt: f64,
        /// rapier's steps.
        steps: usize,
        /// False when rapier's balls had not stopped in time.
        rapier_finished: bool,
        /// Wall-clock seconds spent in rapier.
        rapier_seconds: f64,
    },
    /// The run cannot be made yet (a model is missing), with why.
    Skipped {
        /// Why.
        reason: String,
    },
    /// Our engine failed on the scene.
    Failed {
        /// Why.
        reason: String,
    },
}

/// The result of one (scene, models) run.
#[derive(Clone, Debug, Serialize)]
pub struct RunReport {
    /// Scene name.
    pub scene: String,
    /// Impact models of the run.
    pub models: ImpactModels,
    /// What happened.
    pub outcome: Outcome,
    /// For a chaotic scene: outcome statistics of rapier's shot against an ensemble of ours
    /// (measured, no verdict: see [`crate::ensemble`]).
    pub statistics: Vec<StatRow>,
}

impl RunReport {
    /// True unless the run was compared and failed, or our engine failed. A skipped run passes
    /// (it is listed as skipped).
    pub fn pass(&self) -> bool {
        match &self.outcome {
            Outcome::Compared {
                comparison,
                rapier_finished,
                ..
            } => *rapier_finished && comparison.pass(),
            Outcome::Skipped { .. } => true,
            Outcome::Failed { .. } => false,
        }
    }
}

/// The balls that start in contact with another ball (a pack).
pub fn packed(setup: &Setup) -> Vec<usize> {
    let r = setup.params.ball_radius;
    (0..setup.balls.len())
        .filter(|&i| {
            setup.balls.iter().enumerate().any(|(j, o)| {
                j != i && (setup.balls[i].state.pos - o.state.pos).norm() < 2.0 * r + 1e-6
            })
        })
        .collect()
}

/// What can be compared of a scene. In a scene whose balls start in contact (a pack), the first
/// impact on a packed ball starts a cascade that an event-driven engine resolves as a sequence
/// of pairwise impacts and rapier as one simultaneous solve within a step, after which the
/// outcome is chaotic: only the impacts up to that one are compared, and not the states after
/// it of the packed balls or of the ball that struck the pack (it rebounds from the pack as a
/// whole in rapier, from one ball in ours).
pub fn scope(setup: &Setup, ours: &Record) -> Scope {
    let pack = packed(setup);
    if pack.is_empty() {
        return Scope::default();
    }
    let first = ours
        .impacts
        .iter()
        .position(|i| i.contact.balls().iter().any(|b| pack.contains(b)));
    let mut skip_after = pack;
    if let Some(k) = first {
        skip_after.extend(ours.impacts[k].contact.balls());
    }
    Scope {
        impacts: Some(first.map_or(ours.impacts.len(), |k| k + 1)),
        skip_after,
    }
}

/// rapier's settings for a run with `models`.
pub fn world_config(models: ImpactModels, dt: f64) -> WorldConfig {
    let friction = if models.friction() {
        ImpactFriction::On
    } else {
        ImpactFriction::Off
    };
    WorldConfig::new(dt, friction)
}

/// Both engines' records of `spec` with `models`: ours, rapier's run; or why not.
pub fn run_both(
    spec: &SceneSpec,
    models: ImpactModels,
    cfg: &WorldConfig,
) -> Result<(Record, RapierRun), Outcome> {
    let m = models
        .models()
        .map_err(|reason| Outcome::Skipped { reason })?;
    let setup = Setup {
        models: m,
        ..spec.setup.clone()
    };
    let shot = simulate(&setup, &spec.options).map_err(|e| Outcome::Failed {
        reason: format!("our engine: {e}"),
    })?;
    let (window, slow) = (2.0 * cfg.dt, RESTING_APPROACH);
    let ours = Record::from_shot(&shot).normalised(window, slow);
    let mut rapier = rapier_run::run(&setup, cfg, shot.duration + EXTRA_TIME);
    rapier.record = rapier.record.normalised(window, slow);
    Ok((ours, rapier))
}

/// Runs `spec` with `models` in both engines at rapier time step `dt` and compares them.
pub fn check(spec: &SceneSpec, models: ImpactModels, dt: f64) -> RunReport {
    let report = |outcome| RunReport {
        scene: spec.name.clone(),
        models,
        outcome,
        statistics: Vec::new(),
    };
    let cfg = world_config(models, dt);
    let start = Instant::now();
    let (ours, rapier) = match run_both(spec, models, &cfg) {
        Ok(r) => r,
        Err(outcome) => return report(outcome),
    };
    let seconds = start.elapsed().as_secs_f64();
    let p = spec.setup.params;
    let jaw_radius = spec.setup.table.jaws.first().map_or(0.010, |j| j.radius);
    let budget = Budget {
        dt,
        sink: rapier.sink,
        friction: models.friction(),
        level_cushions: cfg.cushion_contact == CushionContact::Level,
        nose_radius: jaw_solid(&p, jaw_radius, cfg.cushion_contact).0,
        params: p,
    };
    let tol = allowances(&ours, &budget);
    let scope = scope(&spec.setup, &ours);
    let statistics = if scope.impacts.is_some() {
        ensemble_statistics(spec, models, &rapier.record, 2.0 * dt)
    } else {
        Vec::new()
    };
    RunReport {
        statistics,
        ..report(Outcome::Compared {
            comparison: compare(&ours, &rapier.record, &tol, &scope),
            sink: rapier.sink,
            dt,
            steps: rapier.steps,
            rapier_finished: rapier.finished,
            rapier_seconds: seconds,
        })
    }
}

/// rapier's outcome statistics against those of an ensemble of our engine's shots.
fn ensemble_statistics(
    spec: &SceneSpec,
    models: ImpactModels,
    rapier: &Record,
    window: f64,
) -> Vec<StatRow> {
    let Ok(m) = models.models() else {
        return Vec::new();
    };
    let setup = Setup {
        models: m,
        ..spec.setup.clone()
    };
    let members: Vec<Vec<Stat>> = (-HALF_WIDTH..=HALF_WIDTH)
        .filter_map(|k| {
            let s = turned(&setup, k as f64 * HEADING_STEP);
            let shot = simulate(&s, &spec.options).ok()?;
            let rec = Record::from_shot(&shot).normalised(window, RESTING_APPROACH);
            Some(stats(&s, &rec))
        })
        .collect();
    summarise(&members, &stats(&setup, rapier))
}

/// The runs of a scene: the frictionless limit, and with friction when the scene has impacts.
pub fn check_scene(spec: &SceneSpec, dt: f64) -> Vec<RunReport> {
    let first = check(spec, ImpactModels::Frictionless, dt);
    let has_impacts = match &first.outcome {
        Outcome::Compared { comparison, .. } => !comparison.sequence_ours.is_empty(),
        _ => false,
    };
    let mut out = vec![first];
    if has_impacts {
        out.push(check(spec, ImpactModels::Mathavan, dt));
    }
    out
}
