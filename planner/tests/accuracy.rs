//! The planner against positions with a known answer (issues 13 and 23; [`reachable`]): random
//! positions (cue ball, object ball, 0-6 other balls, 12 ft table), a random strike simulated
//! by the engine that pots the object ball in any way (direct, doubled off cushions, planted
//! through another ball, kissed: `Pots::Any`), and the cue ball's end as the target: a plan
//! then exists. The planner must pot the ball and leave the cue ball within 5 mm in at least
//! 95 % of the cases, and every plan must replay to the bit from the scene it writes.

use rand::SeedableRng;
use rand::rngs::ChaCha8Rng;
use snooker_planner::{Problem, Request, ShotKind, plan_problem, reachable, scene_out};
use snooker_scene::parse;
use std::collections::BTreeMap;

const CASES: usize = 200;
const REACH: f64 = 0.005;

#[test]
fn plans_reach_known_targets_and_replay_exactly() {
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    let (mut cases, mut reached, mut shots, mut tried) = (0, 0, 0, 0);
    let mut misses = Vec::new();
    // Per kind of the drawn strike: cases and reached.
    let mut by_kind: BTreeMap<ShotKind, (usize, usize)> = BTreeMap::new();
    while cases < CASES {
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
        cases += 1;
        by_kind.entry(kind).or_default().0 += 1;
        let plan = match plan_problem(&problem, "case") {
            Ok(p) => p,
            Err(e) => {
                misses.push(format!(
                    "{} {e}\n{text}pocket {pocket}, target {target:?}, drawn strike {strike:?}",
                    kind.name()
                ));
                continue;
            }
        };
        shots += plan.shots_simulated;
        assert!(plan.best.potted);
        if plan.best.distance <= REACH {
            reached += 1;
            by_kind.entry(kind).or_default().1 += 1;
        } else {
            misses.push(format!(
                "{} drawn, {:.1} mm ({} planned)\n{text}pocket {pocket}, target {target:?}, \
                 drawn strike {strike:?}",
                kind.name(),
                plan.best.distance * 1e3,
                plan.best.route.kind.name()
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
