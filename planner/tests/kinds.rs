//! Each kind of pot planned where it is the kind asked for: the planned strike, simulated by
//! the engine, pots the ball in the pocket, and its events say it was that kind (a double's
//! object ball met a cushion, a plant's cue ball hit the other ball first, a kiss's object
//! ball met another ball on its way).

use snooker_planner::trial::classify;
use snooker_planner::{Problem, Request, ShotKind, plan_problem};
use snooker_scene::parse;

fn planned_kind(balls: &str, pot: &str, pocket: &str, kind: ShotKind) -> ShotKind {
    let scene = parse(&format!("balls = [{balls}]\n"), "kinds.toml").unwrap();
    let mut req = Request::new(pot, pocket, [0.5, 0.5], &scene.setup.params);
    // Any pot of that kind will do: the target is not the point here.
    req.tolerance = 5.0;
    req.samples = 4;
    req.alternatives = 0;
    req.kinds = vec![kind];
    let problem = Problem::new(&scene, req).unwrap();
    assert!(
        problem.lines().iter().any(|l| l.kind == kind),
        "no {} line found",
        kind.name()
    );
    let plan = plan_problem(&problem, "kinds").unwrap();
    assert!(plan.best.potted);
    assert_eq!(plan.best.route.kind, kind);
    let shot = problem.run(&plan.best.strike.cue()).unwrap();
    classify(&shot, problem.cue(), problem.object(), pocket).expect("potted there")
}

#[test]
fn a_double_is_planned_off_the_cushion() {
    let k = planned_kind(
        r#"{id = "cue", pos = [1.2, 1.0]}, {id = "red", pos = [1.3, 0.3]}"#,
        "red",
        "middle-left",
        ShotKind::Double,
    );
    assert_eq!(k, ShotKind::Double);
}

#[test]
fn a_plant_is_planned_through_the_other_ball() {
    let k = planned_kind(
        r#"{id = "cue", pos = [1.0, 0.9]}, {id = "red1", pos = [2.0, 1.2]}, {id = "red2", pos = [2.6, 1.4]}"#,
        "red2",
        "top-left",
        ShotKind::Plant,
    );
    assert_eq!(k, ShotKind::Plant);
}

#[test]
fn a_kiss_is_planned_off_the_other_ball() {
    let k = planned_kind(
        r#"{id = "cue", pos = [1.0, 0.9]}, {id = "red", pos = [2.4, 1.1]}, {id = "blue", pos = [2.9, 1.25]}"#,
        "red",
        "top-left",
        ShotKind::Kiss,
    );
    assert_eq!(k, ShotKind::Kiss);
}

#[test]
fn a_direct_pot_reads_as_direct() {
    let k = planned_kind(
        r#"{id = "cue", pos = [1.0, 0.9]}, {id = "red", pos = [2.5, 1.2]}"#,
        "red",
        "top-left",
        ShotKind::Direct,
    );
    assert_eq!(k, ShotKind::Direct);
}

#[test]
fn a_set_of_touching_balls_is_planted() {
    // A red touching the blue, their line of centres at the top-right pocket: the ghost-ball
    // geometry degenerates (the blue's ghost lies in the red) and the plant was dropped before
    // any shot was tried: "cannot be potted", exit 1, where a centre-ball strike at the red
    // pots the blue. With a gap of 0.1 mm too.
    for red in [
        "2.955367718634788, 0.3774539516306224",
        "2.9552825425253126, 0.37750634466808536",
    ] {
        let k = planned_kind(
            &format!(
                r#"{{id = "cue", pos = [2.0, 0.9]}}, {{id = "red", pos = [{red}]}}, {{id = "blue", pos = [3.0, 0.35]}}"#
            ),
            "blue",
            "top-right",
            ShotKind::Plant,
        );
        assert_eq!(k, ShotKind::Plant);
    }
}
