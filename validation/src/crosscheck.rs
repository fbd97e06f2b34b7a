//! One cross-check run: a scene with a choice of impact models, simulated by both engines,
//! reduced to digests and compared against the derived tolerances, over the whole shot or
//! stretch by stretch ([`Method`]).

use crate::compare::{Comparison, Scope, compare};
use crate::digest::ShotDigest;
use crate::ensemble::{HALF_WIDTH, HEADING_STEP, Stat, StatRow, stats, summarise, turned};
use crate::rapier_run::{Rapier, RapierRun, Until};
use crate::rapier_world::{ImpactFriction, WorldConfig};
use crate::scenes::ImpactModels;
use crate::shapes::{ContactHeight, jaw_solid};
use crate::stretch::{self, Stretch, Stretches};
use crate::tolerance::{Budget, allowances};
use serde::Serialize;
use snooker_engine::{Setup, Shot, SimOptions, simulate};
use std::time::Instant;

/// rapier's time step chosen by the convergence study (docs/validation.md), s.
pub const DEFAULT_DT: f64 = 1e-4;

/// Extra simulated time rapier is given beyond our engine's shot (or stretch) before it counts
/// as not stopping, s.
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

/// How a run's verdict is reached.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// The whole shot at once: the impact sequences must be the same and every figure within
    /// its tolerance, accumulated over the shot. For runs whose impacts are the same law in
    /// both engines (the frictionless models, the analytic limits), where only the time step
    /// and the soft contact separate them.
    WholeShot,
    /// Stretch by stretch ([`crate::stretch`]): rapier re-seeded from our state after every
    /// impact whose models differ by design, each impact's own difference against its
    /// by-design bound, each stretch between impacts against the derived tolerances. For runs
    /// with such impacts (frictional impacts, landings); their whole-shot comparison is kept
    /// as information.
    Stretches,
}

impl Method {
    /// The method for a run whose impacts have `friction`, our engine's digest being `ours`:
    /// stretch by stretch when one of its impacts differs by design, else the whole shot.
    pub fn for_run(friction: bool, ours: &ShotDigest) -> Method {
        if ours
            .impacts
            .iter()
            .any(|i| stretch::differs_by_design(friction, &i.parties))
        {
            Method::Stretches
        } else {
            Method::WholeShot
        }
    }

    /// Its name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Method::WholeShot => "whole shot",
            Method::Stretches => "stretches",
        }
    }
}

/// A compared run.
#[derive(Clone, Debug, Serialize)]
pub struct Compared {
    /// How the verdict is reached.
    pub method: Method,
    /// The whole shot compared at once: the verdict with [`Method::WholeShot`], information
    /// with [`Method::Stretches`].
    pub whole: Comparison,
    /// The stretches (with [`Method::Stretches`]).
    pub stretches: Vec<Stretch>,
    /// Depth the balls sank into rapier's cloth, m.
    pub sink: f64,
    /// rapier's time step, s.
    pub dt: f64,
    /// rapier's steps over the whole shot.
    pub steps: usize,
    /// False when rapier's balls had not stopped in time (whole shot).
    pub rapier_finished: bool,
    /// Wall-clock seconds spent in both engines.
    pub seconds: f64,
}

impl Compared {
    /// The verdict's comparisons passed.
    pub fn pass(&self) -> bool {
        match self.method {
            Method::WholeShot => self.rapier_finished && self.whole.pass(),
            Method::Stretches => self.stretches.iter().all(Stretch::pass),
        }
    }
}

/// How a run went.
#[derive(Clone, Debug, Serialize)]
#[serde(rename_all = "snake_case", tag = "status")]
pub enum RunOutcome {
    /// Both engines ran and were compared.
    Compared(Box<Compared>),
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

/// The verdict of a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// Compared, and every comparison of its method passed.
    Pass,
    /// Compared, and a comparison of its method failed.
    Fail,
    /// Not run: a model is missing.
    Skip,
    /// Our engine failed on the scene.
    Error,
}

impl Verdict {
    /// The verdict word of reports.
    pub fn word(self) -> &'static str {
        match self {
            Verdict::Pass => "PASS",
            Verdict::Fail => "FAIL",
            Verdict::Skip => "SKIP",
            Verdict::Error => "ERROR",
        }
    }

    /// True unless the run failed (a skipped run is listed as skipped, not failed).
    pub fn ok(self) -> bool {
        matches!(self, Verdict::Pass | Verdict::Skip)
    }
}

/// The result of one (scene, models) run.
#[derive(Clone, Debug, Serialize)]
pub struct RunReport {
    /// Scene name.
    pub scene: String,
    /// Impact models of the run.
    pub models: ImpactModels,
    /// What happened.
    pub outcome: RunOutcome,
    /// For a chaotic scene: outcome statistics of rapier's shot against an ensemble of ours
    /// (measured, no verdict: see [`crate::ensemble`]).
    pub statistics: Vec<StatRow>,
}

impl RunReport {
    /// The run's verdict.
    pub fn verdict(&self) -> Verdict {
        match &self.outcome {
            RunOutcome::Compared(c) if c.pass() => Verdict::Pass,
            RunOutcome::Compared(_) => Verdict::Fail,
            RunOutcome::Skipped { .. } => Verdict::Skip,
            RunOutcome::Failed { .. } => Verdict::Error,
        }
    }

    /// True unless the run was compared and failed, or our engine failed.
    pub fn pass(&self) -> bool {
        self.verdict().ok()
    }

    /// The comparison, if the run was compared.
    pub fn compared(&self) -> Option<&Compared> {
        match &self.outcome {
            RunOutcome::Compared(c) => Some(c),
            _ => None,
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
pub fn scope(setup: &Setup, ours: &ShotDigest) -> Scope {
    let pack = packed(setup);
    if pack.is_empty() {
        return Scope::default();
    }
    let first = ours
        .impacts
        .iter()
        .position(|i| i.parties.balls().iter().any(|b| pack.contains(b)));
    let mut skip_after = pack;
    if let Some(k) = first {
        skip_after.extend(ours.impacts[k].parties.balls());
    }
    Scope {
        impacts: Some(first.map_or(ours.impacts.len(), |k| k + 1)),
        skip_after,
        ..Scope::default()
    }
}

/// rapier's settings for a run with `models`.
pub fn world_config(models: ImpactModels, dt: f64) -> WorldConfig {
    let friction = if models.friction() {
        ImpactFriction::On
    } else {
        ImpactFriction::Off
    };
    WorldConfig {
        compliant_cushion: models.compliant_cushion(),
        ..WorldConfig::new(dt, friction)
    }
}

/// `spec`'s setup with `models`, or why the run cannot be made.
fn setup_with(spec: &SceneSpec, models: ImpactModels) -> Result<Setup, RunOutcome> {
    let m = models
        .models()
        .map_err(|reason| RunOutcome::Skipped { reason })?;
    Ok(Setup {
        models: m,
        ..spec.setup.clone()
    })
}

/// Our engine's shot of `spec` with `models`, or why not.
pub fn our_shot(spec: &SceneSpec, models: ImpactModels) -> Result<Shot, RunOutcome> {
    let setup = setup_with(spec, models)?;
    simulate(&setup, &spec.options).map_err(|e| RunOutcome::Failed {
        reason: format!("our engine: {e}"),
    })
}

/// Both engines' whole-shot digests of `spec` with `models`: ours, rapier's run; or why not.
pub fn run_both(
    spec: &SceneSpec,
    models: ImpactModels,
    cfg: &WorldConfig,
) -> Result<(ShotDigest, RapierRun), RunOutcome> {
    let setup = setup_with(spec, models)?;
    let shot = our_shot(spec, models)?;
    let (window, slow) = (2.0 * cfg.dt, RESTING_APPROACH);
    let ours = ShotDigest::from_shot(&shot, &setup.table).normalised(window, slow);
    let mut rapier = crate::rapier_run::run(&setup, cfg, shot.duration + EXTRA_TIME);
    rapier.digest = rapier.digest.normalised(window, slow);
    Ok((ours, rapier))
}

/// Runs `spec` with `models` in both engines at rapier time step `dt` and compares them with
/// the method of the models.
pub fn check(spec: &SceneSpec, models: ImpactModels, dt: f64) -> RunReport {
    match our_shot(spec, models) {
        Ok(shot) => check_shot(spec, models, dt, &shot),
        Err(outcome) => RunReport {
            scene: spec.name.clone(),
            models,
            outcome,
            statistics: Vec::new(),
        },
    }
}

/// Compares `shot`, our engine's run of `spec` with `models` (as simulated, or altered by a
/// test), with rapier's run of `spec` at time step `dt`.
pub fn check_shot(spec: &SceneSpec, models: ImpactModels, dt: f64, shot: &Shot) -> RunReport {
    let report = |outcome| RunReport {
        scene: spec.name.clone(),
        models,
        outcome,
        statistics: Vec::new(),
    };
    let setup = match setup_with(spec, models) {
        Ok(s) => s,
        Err(outcome) => return report(outcome),
    };
    let cfg = world_config(models, dt);
    let start = Instant::now();
    let (window, slow) = (2.0 * dt, RESTING_APPROACH);
    let ours = ShotDigest::from_shot(shot, &setup.table).normalised(window, slow);
    let method = Method::for_run(models.friction(), &ours);
    let mut rapier = Rapier::new(&setup, &cfg);
    let initial: Vec<_> = setup.balls.iter().map(|b| b.state).collect();
    let whole = rapier.run(0.0, &initial, Until::Rest, shot.duration + EXTRA_TIME);
    let theirs = whole.digest.normalised(window, slow);
    let p = spec.setup.params;
    let jaw_radius = spec.setup.table.jaws.first().map_or(0.010, |j| j.radius);
    let budget = Budget {
        dt,
        sink: whole.sink,
        friction: models.friction(),
        level_cushions: cfg.cushion_contact == ContactHeight::Level,
        nose_radius: jaw_solid(&p, jaw_radius, cfg.cushion_contact).0,
        jaw_contact: jaw_radius + p.cushion_contact_distance(),
        params: p,
    };
    let scope = scope(&spec.setup, &ours);
    let whole_cmp = compare(&ours, &theirs, &allowances(&ours, &budget), &budget, &scope);
    let stretches = match method {
        Method::WholeShot => Vec::new(),
        Method::Stretches => stretch::check(
            &Stretches {
                shot,
                ours: &ours,
                start: initial,
                friction: models.friction(),
                scope: &scope,
                normalise: (window, slow),
                extra_time: EXTRA_TIME,
            },
            &mut rapier,
            &budget,
        ),
    };
    let statistics = if scope.impacts.is_some() {
        ensemble_statistics(spec, models, &theirs, window)
    } else {
        Vec::new()
    };
    RunReport {
        statistics,
        ..report(RunOutcome::Compared(Box::new(Compared {
            method,
            whole: whole_cmp,
            stretches,
            sink: whole.sink,
            dt,
            steps: whole.steps,
            rapier_finished: whole.finished,
            seconds: start.elapsed().as_secs_f64(),
        })))
    }
}

/// rapier's outcome statistics against those of an ensemble of our engine's shots.
fn ensemble_statistics(
    spec: &SceneSpec,
    models: ImpactModels,
    rapier: &ShotDigest,
    window: f64,
) -> Vec<StatRow> {
    let Ok(setup) = setup_with(spec, models) else {
        return Vec::new();
    };
    let members: Vec<Vec<Stat>> = (-HALF_WIDTH..=HALF_WIDTH)
        .filter_map(|k| {
            let s = turned(&setup, k as f64 * HEADING_STEP);
            let shot = simulate(&s, &spec.options).ok()?;
            let d = ShotDigest::from_shot(&shot, &s.table).normalised(window, RESTING_APPROACH);
            Some(stats(&s, &d))
        })
        .collect();
    summarise(&members, &stats(&setup, rapier))
}

/// The runs of a scene: the frictionless limit, and with friction when the scene has impacts;
/// the cushion scenes also with the compliant cushion.
pub fn check_scene(spec: &SceneSpec, dt: f64) -> Vec<RunReport> {
    let first = check(spec, ImpactModels::Frictionless, dt);
    let has_impacts = first.compared().is_some_and(|c| !c.whole.ours.is_empty());
    let mut out = vec![first];
    if has_impacts {
        out.push(check(spec, ImpactModels::Mathavan, dt));
        if spec.name.starts_with("cushion") {
            out.push(check(spec, ImpactModels::Compliant, dt));
        }
    }
    out
}
