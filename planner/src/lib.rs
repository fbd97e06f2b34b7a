//! The shot planner: given the balls where they lie, an object ball, a pocket and a target for
//! the cue ball, the strike (speed, heading, tip offsets, elevation) that pots the ball and
//! leaves the cue ball nearest the target: the question of thesis chapter 7 (§7.1.5,
//! eq. 7.10), which the thesis answered with a genetic algorithm over its forward model in
//! minutes per shot (§7.2.2, §7.3).
//!
//! Here the heading is solved for the pot on the engine's own result ([`aim`]), the rest is a
//! grid of starts and Nelder–Mead per route of the cue ball ([`search`]), all simulated in
//! parallel, and the shots found are ranked by their pot probability under execution noise
//! ([`robust`]) before their distance. Every shot is simulated exactly as `snooker simulate`
//! runs the scene with that `[cue]` ([`scene_out`] writes it), so a plan replays to the bit.
//!
//! ```
//! use snooker_planner::{Request, plan};
//! let scene = snooker_scene::parse(
//!     r#"balls = [{id = "cue", pos = [1.0, 0.8]}, {id = "red", pos = [1.3, 1.3]}]"#,
//!     "doc.toml",
//! ).unwrap();
//! let mut request = Request::new("red", "middle-left", [1.5, 1.2], &scene.setup.params);
//! request.tolerance = 0.005;
//! request.samples = 16;
//! let plan = plan(&scene, request).unwrap();
//! assert!(plan.best.potted);
//! ```

pub mod aim;
pub mod cancel;
pub mod explore;
pub mod line;
pub mod noise;
pub mod problem;
pub mod reachable;
pub mod robust;
pub mod scene_out;
pub mod search;
pub mod trial;

pub use aim::Stroke;
pub use cancel::Cancel;
pub use explore::{Objective, Scored, explore, refine};
pub use line::{Line, ShotKind};
pub use noise::{StrikeErrors, execute, rng_for};
pub use problem::{
    Bounds, Interval, Noise, NoiseComponent, PlanError, Problem, Request, RequestField,
    StrikeVariable,
};
pub use robust::Robustness;
pub use trial::{Fault, Route, Trial};

use serde::Serialize;
use snooker_engine::Cue;
use snooker_scene::Scene;
use std::time::Instant;

/// A strike as the scene file's `[cue]` table gives it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StrikeSpec {
    /// The ball struck.
    pub ball: String,
    /// Cue speed, m/s.
    pub speed: f64,
    /// Heading, rad.
    pub aim: f64,
    /// Tip offsets (side, height), m.
    pub offset: [f64; 2],
    /// Elevation, rad.
    pub elevation: f64,
}

impl StrikeSpec {
    /// The strike `cue` on ball `ball`.
    pub fn new(ball: &str, cue: &Cue) -> StrikeSpec {
        StrikeSpec {
            ball: ball.into(),
            speed: cue.speed,
            aim: cue.aim,
            offset: cue.offset,
            elevation: cue.elevation,
        }
    }

    /// The engine's cue strike.
    pub fn cue(&self) -> Cue {
        Cue {
            speed: self.speed,
            aim: self.aim,
            offset: self.offset,
            elevation: self.elevation,
        }
    }
}

/// The cue ball's route, for reading.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RouteSpec {
    /// The kind of pot aimed: `direct`, `double`, `plant` or `kiss`.
    pub kind: ShotKind,
    /// The ball a plant strikes first or a kiss glances off (its id), or the cushions a
    /// double's object ball meets (names, in order); empty for a direct pot.
    pub via: Vec<String>,
    /// Cushions met by the cue ball after the object ball (at most three).
    pub cushions: Vec<String>,
    /// "screw", "stun" or "follow" (tip below, near or above the centre).
    pub spin: &'static str,
}

/// One planned shot.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlannedShot {
    /// The strike.
    pub strike: StrikeSpec,
    /// True when it pots the object ball in the pocket with no foul (without noise).
    pub potted: bool,
    /// Where the cue ball stops, m.
    pub cue_final: [f64; 2],
    /// Its distance from the target, m.
    pub distance: f64,
    /// The cue ball's route.
    pub route: RouteSpec,
    /// Under execution noise.
    pub robustness: Robustness,
}

/// The answer (formats.md, "Plan").
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Plan {
    /// The scene's name.
    pub scene: String,
    /// The object ball.
    pub pot: String,
    /// The pocket.
    pub pocket: String,
    /// The cue ball's target, m.
    pub target: [f64; 2],
    /// Distance that counts as reached, m.
    pub tolerance: f64,
    /// True when the best shot leaves the cue ball within the tolerance of the target.
    pub reached: bool,
    /// The shot chosen: among those within the tolerance, the likeliest to pot under noise
    /// (then the nearest); if none is within it, the nearest.
    pub best: PlannedShot,
    /// Other shots, each on its own route of the cue ball, in the same order.
    pub alternatives: Vec<PlannedShot>,
    /// Shots simulated in all.
    pub shots_simulated: u64,
    /// Wall time, s.
    pub wall_time: f64,
}

/// "direct pot, double, plant or kiss" for the kinds given.
fn kinds_phrase(kinds: &[ShotKind]) -> String {
    let names: Vec<&str> = kinds
        .iter()
        .map(|k| match k {
            ShotKind::Direct => "direct pot",
            k => k.name(),
        })
        .collect();
    match names.split_last() {
        Some((last, [])) => last.to_string(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
        None => String::new(),
    }
}

/// Plans on `scene` (its `[cue]` ignored).
pub fn plan(scene: &Scene, request: Request) -> Result<Plan, PlanError> {
    let problem = Problem::new(scene, request)?;
    plan_problem(&problem, &scene.name)
}

/// Plans a checked problem (the command watches [`Problem::shots`] for its progress bar).
pub fn plan_problem(problem: &Problem, scene_name: &str) -> Result<Plan, PlanError> {
    let start = Instant::now();
    let req = &problem.request;
    let found = search::search(problem, req.alternatives + 1);
    if found.is_empty() {
        // Shots that could not finish say more than "no line is open" when they are many.
        let unfinished = match problem.unfinished() {
            0 => String::new(),
            n => format!(
                "; {n} of the shots could not finish within the scene's [sim] limits \
                 (max_time, max_events)"
            ),
        };
        return Err(PlanError::CannotPot(format!(
            "no strike within the bounds pots \"{}\" in {} without a foul ({} shots tried): \
             no {} is open, or the cue ball cannot reach a contact that sends it there{unfinished}",
            req.pot,
            req.pocket,
            problem.shots(),
            kinds_phrase(&req.kinds)
        )));
    }
    let cue_id = problem.setup.balls[problem.cue].id.clone();
    let mut shots: Vec<PlannedShot> = found
        .iter()
        .enumerate()
        .map(|(k, f)| {
            let t = &f.trial;
            let line = &t.route.line;
            let via = match (line.ball, line.kind) {
                (Some(b), _) => vec![problem.setup.balls[b].id.clone()],
                (None, _) => line
                    .cushions
                    .iter()
                    .map(|&c| problem.setup.table.cushions[c].name.clone())
                    .collect(),
            };
            PlannedShot {
                strike: StrikeSpec::new(&cue_id, &t.cue),
                potted: t.pots(),
                cue_final: [t.cue_final.x, t.cue_final.y],
                distance: f.distance,
                route: RouteSpec {
                    kind: line.kind,
                    via,
                    cushions: t.route.cushions.clone(),
                    spin: match t.route.spin {
                        -1 => "screw",
                        0 => "stun",
                        _ => "follow",
                    },
                },
                robustness: problem.robustness(&t.cue, line, k as u64),
            }
        })
        .collect();
    let tol = req.tolerance;
    shots.sort_by(|a, b| {
        let (ra, rb) = (a.distance <= tol, b.distance <= tol);
        rb.cmp(&ra).then_with(|| {
            if ra && rb {
                b.robustness
                    .pot_probability
                    .total_cmp(&a.robustness.pot_probability)
                    .then(a.distance.total_cmp(&b.distance))
            } else {
                a.distance.total_cmp(&b.distance)
            }
        })
    });
    let best = shots.remove(0);
    shots.truncate(req.alternatives);
    Ok(Plan {
        scene: scene_name.to_string(),
        pot: req.pot.clone(),
        pocket: req.pocket.clone(),
        target: req.target,
        tolerance: tol,
        reached: best.distance <= tol,
        best,
        alternatives: shots,
        shots_simulated: problem.shots(),
        wall_time: start.elapsed().as_secs_f64(),
    })
}
