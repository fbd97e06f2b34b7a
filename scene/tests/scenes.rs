//! Every scene in the repository's `scenes/` loads, simulates cleanly (`check_shot`: the
//! invariants of `snooker_engine::audit`) and does what its name says.

use snooker_engine::audit::{audit, report};
use snooker_engine::motion::Transition;
use snooker_engine::{Ending, EventKind, Setup, Shot, SimOptions, simulate};
use snooker_scene as scene;
use std::path::Path;

/// Asserts that `shot` ended at rest and broke none of the invariants of
/// [`snooker_engine::audit`].
fn check_shot(setup: &Setup, shot: &Shot) {
    assert_eq!(shot.ending, Ending::AtRest, "the shot did not end at rest");
    if let Some(broken) = report(&audit(setup, shot)) {
        panic!("{broken}");
    }
}

fn run(name: &str) -> (scene::Scene, Shot) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../scenes")
        .join(format!("{name}.toml"));
    let sc = scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let shot = simulate(&sc.setup, &sc.options).unwrap_or_else(|e| panic!("{name}: {e}"));
    check_shot(&sc.setup, &shot);
    (sc, shot)
}

fn cushions_of(shot: &Shot, ball: usize) -> Vec<String> {
    shot.events
        .iter()
        .filter(|e| e.kind == EventKind::BallCushion && e.balls == [ball])
        .map(|e| e.feature.clone().unwrap())
        .collect()
}

#[test]
fn every_scene_file_simulates_cleanly() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    let mut n = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let sc = scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
            let shot = simulate(&sc.setup, &SimOptions::default()).unwrap();
            check_shot(&sc.setup, &shot);
            n += 1;
        }
    }
    assert!(n >= 15, "only {n} scenes");
}

#[test]
fn cushion_scenes_hit_the_number_of_cushions_they_are_named_for() {
    for (name, n) in [("one-cushion", 1), ("two-cushion", 2), ("three-cushion", 3)] {
        let (_, shot) = run(name);
        assert_eq!(
            cushions_of(&shot, 0).len(),
            n,
            "{name}: {:?}",
            cushions_of(&shot, 0)
        );
    }
}

#[test]
fn screw_comes_back_follow_runs_on_stun_stops_near_the_contact() {
    let start = |sc: &scene::Scene| sc.setup.balls[0].state.pos.x;
    let (sc, shot) = run("screw");
    let end = shot.final_states()[0].pos.x;
    assert!(
        end < start(&sc),
        "screw: cue ball ends at {end}, started at {}",
        start(&sc)
    );
    // Where the cue ball is just after it meets the object ball.
    let contact = |shot: &Shot| {
        let hit = shot.events.iter().find(|e| e.kind == EventKind::BallBall);
        hit.unwrap().after[0].pos.x
    };
    let (_, shot) = run("follow");
    assert!(shot.final_states()[0].pos.x > contact(&shot) + 0.1);
    let (_, shot) = run("stun");
    let c = contact(&shot);
    let end = shot.final_states()[0].pos.x;
    assert!((end - c).abs() < 0.2, "stun moved on {:.3} m", end - c);
}

#[test]
fn the_cut_is_thirty_degrees() {
    let (_, shot) = run("cut-30");
    let e = shot
        .events
        .iter()
        .find(|e| e.kind == EventKind::BallBall)
        .unwrap();
    let n = (e.before[1].pos - e.before[0].pos).normalize();
    let v = e.before[0].vel.normalize();
    let cut = n.dot(&v).acos().to_degrees();
    assert!((cut - 30.0).abs() < 0.01, "{cut}");
}

#[test]
fn table_i_scenes_meet_at_the_measured_speed_and_cut() {
    let data = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../data/thesis_oblique_collisions.csv"),
    )
    .unwrap();
    let rows: Vec<Vec<f64>> = data
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("speed_in"))
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 5);
    for (k, row) in rows.iter().enumerate() {
        let (_, shot) = run(&format!("table-i-{}", k + 1));
        let e = shot
            .events
            .iter()
            .find(|e| e.kind == EventKind::BallBall)
            .unwrap();
        let cue = e.before[0];
        assert!(
            (cue.vel.norm() - row[0]).abs() < 1e-9,
            "speed {}",
            cue.vel.norm()
        );
        assert!(
            cue.slip(shot.params.ball_radius).norm() < 1e-9,
            "must arrive rolling"
        );
        let n = (e.before[1].pos - cue.pos).normalize();
        let cut = n.dot(&cue.vel.normalize()).acos().to_degrees();
        assert!((cut - row[1]).abs() < 1e-3, "cut {cut} vs {}", row[1]);
    }
}

#[test]
fn the_perpendicular_rebound_stays_on_its_line() {
    let (_, shot) = run("cushion-rebound");
    assert_eq!(cushions_of(&shot, 0), ["top"]);
    assert!((shot.final_states()[0].pos.y - 0.889).abs() < 1e-12);
}

#[test]
fn the_chapter_7_example_strikes_as_the_thesis_describes() {
    let (sc, shot) = run("chapter7-example");
    let struck = sc.strike.as_ref().unwrap();
    let (cue, strike) = (&struck.cue, &struck.strike);
    assert!((cue.aim - 0.515).abs() < 1e-12);
    // The first contact is with the object ball (thesis fig. 7.20).
    let first = shot
        .events
        .iter()
        .find(|e| e.kind != EventKind::Transition(snooker_engine::motion::Transition::SlideToRoll))
        .unwrap();
    assert_eq!(first.kind, EventKind::BallBall);
    assert!(strike.squirt.abs() > 0.0);
}

/// Speeds once sliding has ended (first slide_to_roll of each ball after the impact) for a
/// scene file.
fn post_slip_speeds(file: &str) -> (f64, f64) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../scenes")
        .join(file);
    let sc = scene::load(&path).unwrap();
    let shot = snooker_engine::simulate(&sc.setup, &sc.options).unwrap();
    let speed = |ball: usize| {
        shot.events
            .iter()
            .find(|e| e.kind == EventKind::Transition(Transition::SlideToRoll) && e.balls == [ball])
            .map(|e| e.after[0].vel.norm())
            .unwrap()
    };
    (speed(0), speed(1))
}

#[test]
fn table_i_collisions_within_three_percent() {
    // Thesis appendix III (AJP 2009), Table I: rolling cue ball, measured speeds once sliding
    // has ended. The ideal Wallace & Schroeder model is 6.4 % off on average.
    let data = include_str!("../../data/thesis_oblique_collisions.csv");
    let rows: Vec<Vec<f64>> = data
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("speed_in"))
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let (mut ours, mut ws) = (Vec::new(), Vec::new());
    for (k, row) in rows.iter().enumerate() {
        let (cue, obj) = post_slip_speeds(&format!("table-i-{}.toml", k + 1));
        ours.push(rel(cue, row[2]));
        ours.push(rel(obj, row[3]));
        ws.push(rel(row[4], row[2]));
        ws.push(rel(row[5], row[3]));
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    assert!((mean(&ws) - 0.064).abs() < 0.001, "W&S error {}", mean(&ws));
    assert!(
        mean(&ours) <= 0.03,
        "mean relative error {:.4}",
        mean(&ours)
    );
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-12)
}
