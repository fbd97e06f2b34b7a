//! Planning a shot for the page (`snooker plan`'s question: pot this ball in that pocket and
//! leave the cue ball near the target), as a job: the planner's request checked up front
//! (HTTP 400 naming the request's key), then the search run with its progress watched and its
//! cancellation flag raised on request or at the wall-time limit. The answer is the plan
//! (formats.md, "Plan"), the planned scene, the best shot's paths and the alternatives' cue
//! ball paths; the best shot is replayed from the scene written and must end where the
//! planner saw it, to the bit, as the command checks.

use crate::body::REQUEST;
use crate::error::ApiError;
use crate::input::{self, CheckedScene};
use crate::jobs::Job;
use crate::limits::Limits;
use crate::paths::Path;
use crate::shot::{self, ShotView};
use serde::{Deserialize, Serialize};
use serde_json::Value;
use snooker_planner::{NoiseComponent, Plan, PlanError, Problem, Request, StrikeSpec};
use snooker_scene::file::Numbers;
use snooker_scene::{CueSpec, SceneFile};
use std::collections::BTreeMap;
use std::sync::Arc;

/// A request to plan.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlanRequest {
    /// The position (the scene file's keys; its `cue` is ignored).
    pub scene: Value,
    /// The ball to pot (its id).
    pub pot: String,
    /// The pocket.
    pub pocket: String,
    /// Where the cue ball should stop (x, y), m: exactly two numbers, as a scene's `pos`.
    pub target: Numbers<2>,
    /// The ball struck (default `cue`).
    #[serde(default)]
    pub cue_ball: Option<String>,
    /// Distance that counts as reached, m.
    #[serde(default)]
    pub tolerance: Option<f64>,
    /// Noise samples per shot.
    #[serde(default)]
    pub samples: Option<usize>,
    /// Most alternatives.
    #[serde(default)]
    pub alternatives: Option<usize>,
    /// Seed of the noise samples.
    #[serde(default)]
    pub seed: Option<u64>,
    /// Standard deviations of the execution noise by component name (the planner's).
    #[serde(default)]
    pub noise: Option<BTreeMap<String, f64>>,
}

/// The answer of a plan job.
#[derive(Debug, Clone, Serialize)]
pub struct PlanView {
    /// The plan (formats.md, "Plan").
    pub plan: Plan,
    /// The scene with the best strike as its `cue` (the scene file's keys).
    pub scene: Value,
    /// The same as a scene file: `snooker simulate` on it replays the best shot.
    pub scene_toml: String,
    /// The best shot, simulated from that scene.
    pub best: ShotView,
    /// Each alternative's cue ball path, in the plan's order.
    pub alternatives: Vec<Path>,
}

/// A checked plan: the problem and what the job needs.
pub struct Checked {
    scene: CheckedScene,
    problem: Problem,
    limits: Limits,
}

fn too_many(key: &str, what: &str, given: usize, most: usize) -> ApiError {
    ApiError::bad(
        REQUEST,
        key,
        format!("{given} {what}: the server takes at most {most}"),
    )
}

/// Checks `req` as the planner does, and against the server's limits.
pub fn check(req: PlanRequest, limits: &Limits) -> Result<Checked, ApiError> {
    let checked = input::scene(&req.scene, limits)?;
    let p = checked.scene.setup.params;
    let mut request = Request::new(&req.pot, &req.pocket, req.target.0, &p);
    if let Some(c) = req.cue_ball {
        request.cue_ball = c;
    }
    if let Some(t) = req.tolerance {
        if t < limits.plan_tolerance {
            return Err(ApiError::bad(
                REQUEST,
                "tolerance",
                format!(
                    "{t} m: the server plans to {} m at the finest",
                    limits.plan_tolerance
                ),
            ));
        }
        request.tolerance = t;
    }
    if let Some(n) = req.samples {
        if n > limits.plan_samples {
            return Err(too_many("samples", "samples", n, limits.plan_samples));
        }
        request.samples = n;
    }
    if let Some(n) = req.alternatives {
        if n > limits.plan_alternatives {
            return Err(too_many(
                "alternatives",
                "alternatives",
                n,
                limits.plan_alternatives,
            ));
        }
        request.alternatives = n;
    }
    if let Some(s) = req.seed {
        request.seed = s;
    }
    for (name, sd) in req.noise.unwrap_or_default() {
        let c = NoiseComponent::from_name(&name).ok_or_else(|| {
            let names: Vec<&str> = NoiseComponent::ALL.iter().map(|c| c.name()).collect();
            ApiError::bad(
                REQUEST,
                &format!("noise.{name}"),
                format!("unknown noise `{name}` ({})", names.join(", ")),
            )
        })?;
        request.noise.set(c, sd);
    }
    let problem = Problem::new(&checked.scene, request).map_err(plan_error)?;
    Ok(Checked {
        scene: checked,
        problem,
        limits: *limits,
    })
}

/// A planner error as the API says it: the request's field, as the planner names it.
fn plan_error(e: PlanError) -> ApiError {
    match e {
        PlanError::BadInput { field, reason } => ApiError::bad(REQUEST, &field.to_string(), reason),
        PlanError::CannotPot(why) => ApiError::unfinished(REQUEST, why),
    }
}

/// The scene file `file` with `strike` as its `cue`.
fn with_strike(file: &SceneFile, strike: &StrikeSpec) -> SceneFile {
    let mut f = file.clone();
    f.cue = Some(
        CueSpec::new(strike.ball.clone(), strike.speed, strike.aim)
            .with_offset(strike.offset)
            .with_elevation(strike.elevation),
    );
    f
}

/// Runs the plan as job `job`.
pub fn run(checked: Checked, job: &Job) -> Result<Value, ApiError> {
    let Checked {
        scene,
        problem,
        limits,
    } = checked;
    let problem = Arc::new(problem.with_cancel(job.cancel.clone()));
    job.watch(problem.clone());
    job.set_note(format!(
        "planning {} in {}",
        problem.request().pot,
        problem.request().pocket
    ));
    let plan = snooker_planner::plan_problem(&problem, &scene.scene.name);
    if problem.cancelled() {
        return Err(ApiError::new(409, REQUEST, "", "cancelled"));
    }
    let plan = plan.map_err(plan_error)?;
    job.set_note("replaying the best shot");
    let planned = with_strike(&scene.file, &plan.best.strike);
    let value = input::scene_value(&planned)?;
    let replayed = input::scene(&value, &limits)?;
    let shot = shot::simulate(&replayed.scene, input::SCENE)?;
    let end = shot.final_states()[problem.cue()].pos;
    if [end.x.to_bits(), end.y.to_bits()] != plan.best.cue_final.map(f64::to_bits) {
        return Err(ApiError::internal(format!(
            "the planned shot does not replay: the cue ball ends at ({}, {}), the plan says ({}, {})",
            end.x, end.y, plan.best.cue_final[0], plan.best.cue_final[1]
        )));
    }
    let best = shot::view(&replayed.scene, &shot, limits.path_rate.min(120.0), &limits);
    let mut alternatives = Vec::new();
    for alt in &plan.alternatives {
        let v = input::scene_value(&with_strike(&scene.file, &alt.strike))?;
        let s = input::scene(&v, &limits)?;
        let alt_shot = shot::simulate(&s.scene, input::SCENE)?;
        let mut paths = crate::paths::sample(&alt_shot, 60.0, limits.path_points);
        alternatives.push(paths.balls.swap_remove(problem.cue()));
    }
    let view = PlanView {
        scene_toml: planned.to_toml(),
        scene: value,
        plan,
        best,
        alternatives,
    };
    serde_json::to_value(view).map_err(|e| ApiError::internal(e.to_string()))
}
