//! The planner against positions with a known answer (issues 13 and 23; [`reachable`]): random
//! positions (cue ball, object ball, 0-6 other balls, 12 ft table), a random strike simulated
//! by the engine that pots the object ball in any way (direct, doubled off cushions, planted
//! through another ball, kissed: `Pots::Any`), and the cue ball's end as the target: a plan
//! then exists. The planner must pot the ball and leave the cue ball within 5 mm in at least
//! 95 % of the cases, and every plan must replay to the bit from the scene it writes.

use rand::SeedableRng;
use rand::rngs::ChaCha8Rng;
use rayon::prelude::*;
use snooker_planner::{Problem, Request, ShotKind, plan_problem, reachable, scene_out};
use snooker_scene::parse;
use std::collections::BTreeMap;

const CASES: usize = 200;
const REACH: f64 = 0.005;

/// One drawn case: its scene, the drawn strike's kind and pocket, and the problem posed.
struct Case {
    text: String,
    pocket: String,
    target: [f64; 2],
    kind: ShotKind,
    strike: String,
    problem: Problem,
}

/// What planning one case gave: reached within [`REACH`], or why not; shots simulated.
struct Outcome {
    reached: bool,
    miss: Option<String>,
    shots: u64,
}

/// Plans one case and replays the plan from the scene it writes (to the bit).
fn plan_case(c: &Case) -> Outcome {
    let plan = match plan_problem(&c.problem, "case") {
        Ok(p) => p,
        Err(e) => {
            return Outcome {
                reached: false,
                miss: Some(format!(
                    "{} {e}\n{}pocket {}, target {:?}, drawn strike {}",
                    c.kind.name(),
                    c.text,
                    c.pocket,
                    c.target,
                    c.strike
                )),
                shots: 0,
            };
        }
    };
    assert!(plan.best.potted);
    let reached = plan.best.distance <= REACH;
    let miss = (!reached).then(|| {
        format!(
            "{} drawn, {:.1} mm ({} planned)\n{}pocket {}, target {:?}, drawn strike {}",
            c.kind.name(),
            plan.best.distance * 1e3,
            plan.best.route.kind.name(),
            c.text,
            c.pocket,
            c.target,
            c.strike
        )
    });
    // Replays to the bit from the scene written.
    let out = scene_out::with_strike(&c.text, &plan.best.strike).unwrap();
    let replayed = parse(&out, "out.toml").unwrap();
    let shot = snooker_engine::simulate(&replayed.setup, &replayed.options).unwrap();
    let end = shot.final_states()[c.problem.cue()].pos;
    assert_eq!(
        [end.x.to_bits(), end.y.to_bits()],
        plan.best.cue_final.map(f64::to_bits),
        "{out}"
    );
    Outcome {
        reached,
        miss,
        shots: plan.shots_simulated,
    }
}

#[test]
fn plans_reach_known_targets_and_replay_exactly() {
    // The cases are drawn in order from one generator, then planned in parallel (each plan is
    // deterministic), so the set and every result are those of a sequential run.
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    let mut drawn = Vec::new();
    let mut tried = 0;
    while drawn.len() < CASES {
        tried += 1;
        assert!(tried < 200 * CASES, "too few potting strikes");
        let Some(reachable::Reachable {
            text,
            pocket,
            target,
            kind,
            strike,
        }) = reachable::draw(&mut rng, reachable::Pots::Any)
        else {
            continue;
        };
        let scene = parse(&text, "case.toml").unwrap();
        // The target may lie where the planner refuses it (touching a ball that stayed).
        let mut req = Request::new("obj", &pocket, target, &scene.setup.params);
        req.tolerance = REACH;
        req.samples = 8;
        req.alternatives = 0;
        let Ok(problem) = Problem::new(&scene, req) else {
            continue;
        };
        let strike = format!("{strike:?}");
        drawn.push(Case {
            text,
            pocket,
            target,
            kind,
            strike,
            problem,
        });
    }
    let outcomes: Vec<Outcome> = drawn.par_iter().map(plan_case).collect();
    let cases = drawn.len();
    let (mut reached, mut shots) = (0, 0);
    let mut misses = Vec::new();
    // Per kind of the drawn strike: cases and reached.
    let mut by_kind: BTreeMap<ShotKind, (usize, usize)> = BTreeMap::new();
    for (c, o) in drawn.iter().zip(outcomes) {
        let entry = by_kind.entry(c.kind).or_default();
        entry.0 += 1;
        if o.reached {
            reached += 1;
            entry.1 += 1;
        }
        shots += o.shots;
        misses.extend(o.miss);
    }
    let share = reached as f64 / cases as f64;
    for (kind, (n, ok)) in &by_kind {
        eprintln!("{}: {ok} of {n} reached", kind.name());
    }
    for m in &misses {
        eprintln!("missed: {}", m.lines().next().unwrap_or(""));
    }
    eprintln!(
        "{reached} of {cases} within {} mm ({:.1} %), {} shots per plan on average",
        REACH * 1e3,
        100.0 * share,
        shots / cases as u64
    );
    assert!(
        share >= 0.95,
        "{share}: misses:\n{}",
        misses.join("\n---\n")
    );
}
