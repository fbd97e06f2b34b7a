//! The planner against positions with a known answer (issue 13; [`reachable`]): random
//! positions (cue ball, object ball, 0-6 other balls, 12 ft table), a random strike simulated by
//! the engine that pots the object ball cleanly and directly (the planner aims direct pots, not
//! doubles or plants), and the cue ball's end as the target: a plan then exists.
//! The planner must pot the ball and leave the cue ball within 5 mm in at least 95 % of the
//! cases, and every plan must replay to the bit from the scene it writes.

use rand::SeedableRng;
use rand::rngs::ChaCha8Rng;
use snooker_planner::{Problem, Request, plan_problem, reachable, scene_out};
use snooker_scene::parse;

const CASES: usize = 200;
const REACH: f64 = 0.005;

#[test]
fn plans_reach_known_targets_and_replay_exactly() {
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    let (mut cases, mut reached, mut shots, mut tried) = (0, 0, 0, 0);
    let mut misses = Vec::new();
    while cases < CASES {
        tried += 1;
        assert!(tried < 200 * CASES, "too few potting strikes");
        let Some(reachable::Reachable {
            text,
            pocket,
            target,
            ..
        }) = reachable::draw(&mut rng)
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
        cases += 1;
        let plan = match plan_problem(&problem, "case") {
            Ok(p) => p,
            Err(e) => {
                misses.push(format!("{e}\n{text}pocket {pocket}, target {target:?}"));
                continue;
            }
        };
        shots += plan.shots_simulated;
        assert!(plan.best.potted);
        if plan.best.distance <= REACH {
            reached += 1;
        } else {
            misses.push(format!(
                "{:.1} mm\n{text}pocket {pocket}, target {target:?}",
                plan.best.distance * 1e3
            ));
        }
        // Replays to the bit from the scene written.
        let out = scene_out::with_strike(&text, &plan.best.strike).unwrap();
        let replayed = parse(&out, "out.toml").unwrap();
        let shot = snooker_engine::simulate(&replayed.setup, &replayed.options).unwrap();
        let end = shot.final_states()[problem.cue].pos;
        assert_eq!(
            [end.x.to_bits(), end.y.to_bits()],
            plan.best.cue_final.map(f64::to_bits),
            "{out}"
        );
    }
    let share = reached as f64 / cases as f64;
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
