//! The situations event-driven simulators are known to get wrong (peers.md: missed collisions,
//! corner escapes, endless simulations, false t = 0 collisions, division by zero when a ball
//! runs along a rail, zero friction hanging): each must end correctly.

mod common;

use snooker_engine::cue::{self, Cue};
use snooker_engine::{
    Ball, BallKind, BallState, EventKind, Models, Motion, Params, Setup, SimError, SimOptions,
    Table, Vec3, simulate,
};

fn ball(id: &str, pos: Vec3, vel: Vec3, spin: Vec3) -> Ball {
    Ball {
        id: id.into(),
        kind: BallKind::from_id(id),
        state: BallState {
            pos,
            vel,
            spin,
            motion: Motion::Stationary,
        },
    }
}

fn rolling(id: &str, x: f64, y: f64, v: Vec3, p: &Params) -> Ball {
    ball(
        id,
        Vec3::new(x, y, p.ball_radius),
        v,
        Vec3::z().cross(&v) / p.ball_radius,
    )
}

fn resting(id: &str, x: f64, y: f64, p: &Params) -> Ball {
    ball(
        id,
        Vec3::new(x, y, p.ball_radius),
        Vec3::zeros(),
        Vec3::zeros(),
    )
}

fn setup(table: Table, balls: Vec<Ball>) -> Setup {
    Setup {
        table,
        params: Params::default(),
        models: Models::default(),
        balls,
    }
}

fn run(s: &Setup) -> snooker_engine::Shot {
    let shot = simulate(s, &SimOptions::default()).expect("simulation failed");
    common::check_shot(s, &shot);
    shot
}

#[test]
fn a_ball_rolling_along_a_cushion_never_touches_it_or_escapes() {
    let p = Params::default();
    let d = p.cushion_contact_distance();
    // Exactly at the contact distance, moving parallel: no impact, no division by zero.
    let s = setup(
        Table::snooker(&Default::default()),
        vec![rolling("cue", 0.3, d, Vec3::new(1.2, 0.0, 0.0), &p)],
    );
    let shot = run(&s);
    assert!(
        shot.events.iter().all(|e| e.kind != EventKind::BallCushion),
        "{:?}",
        shot.events
    );
}

#[test]
fn a_ball_running_along_the_cushion_into_the_jaw_is_handled() {
    // Close to the nose, fast, along the rail into the middle pocket's jaw: it either drops or
    // bounces off the jaw; it must never pass through it.
    let p = Params::default();
    let d = p.cushion_contact_distance();
    for offset in [0.0, 0.002, 0.005, 0.01, 0.02] {
        let s = setup(
            Table::snooker(&Default::default()),
            vec![rolling(
                "cue",
                0.5,
                d + offset,
                Vec3::new(2.5, 0.0, 0.0),
                &p,
            )],
        );
        run(&s);
    }
}

#[test]
fn grazing_a_jaw_tangentially() {
    // Aim the ball's path to pass the jaw arc at exactly its contact radius.
    let p = Params::default();
    let table = Table::snooker(&Default::default());
    let jaw = table
        .jaws
        .iter()
        .find(|j| j.name.starts_with("middle-right"))
        .unwrap()
        .clone();
    let rho = jaw.radius + p.cushion_contact_distance();
    for dy in [-1e-9, 0.0, 1e-9, 1e-6] {
        let y = jaw.centre.y + rho + dy;
        let s = setup(
            table.clone(),
            vec![rolling("cue", 1.0, y, Vec3::new(1.5, 0.0, 0.0), &p)],
        );
        run(&s);
    }
}

#[test]
fn equal_velocities_make_a_degenerate_quartic_and_no_false_contact() {
    // Two balls rolling side by side at the same velocity, touching: the relative path is
    // constant; there must be no collision at all (no false t = 0 event).
    let p = Params::default();
    let v = Vec3::new(1.0, 0.0, 0.0);
    let s = setup(
        Table::open(),
        vec![
            rolling("a", 0.0, 0.0, v, &p),
            rolling("b", 0.0, 2.0 * p.ball_radius, v, &p),
        ],
    );
    let shot = run(&s);
    assert!(shot.events.iter().all(|e| e.kind != EventKind::BallBall));
}

#[test]
fn balls_at_rest_in_contact_stay_put() {
    let p = Params::default();
    let r = p.ball_radius;
    let s = setup(
        Table::open(),
        vec![
            resting("a", 0.0, 0.0, &p),
            resting("b", 2.0 * r, 0.0, &p),
            resting("c", r, 3f64.sqrt() * r, &p),
        ],
    );
    let shot = run(&s);
    assert!(shot.events.is_empty());
}

#[test]
fn simultaneous_impacts_resolve_in_a_fixed_order_and_conserve_momentum() {
    // Two balls hit a third from opposite sides at the same instant.
    let p = Params::default();
    let r = p.ball_radius;
    let v = Vec3::new(1.0, 0.0, 0.0);
    let mut s = setup(
        Table::open(),
        vec![
            resting("mid", 0.0, 0.0, &p),
            rolling("left", -0.3, 0.0, v, &p),
            rolling("right", 0.3, 0.0, -v, &p),
        ],
    );
    // Frictionless impacts: the cloth takes no momentum during them.
    s.models = Models {
        ball_ball: snooker_engine::BallBallModel::Frictionless,
        cushion: snooker_engine::CushionModel::Frictionless,
    };
    let shot = run(&s);
    let impacts: Vec<_> = shot
        .events
        .iter()
        .filter(|e| e.kind == EventKind::BallBall)
        .collect();
    assert!(impacts.len() >= 2);
    let t0 = impacts[0].t;
    let burst: Vec<_> = impacts.iter().filter(|e| e.t == t0).collect();
    assert!(burst.len() >= 2, "both impacts at the same instant");
    // Fixed order: the lower ball indices first.
    assert_eq!(burst[0].balls, vec![0, 1]);
    // Pairwise resolution conserves momentum through the burst.
    let momentum = |t: f64| -> f64 { shot.tracks.iter().map(|tr| tr.state_at(t, &p).vel.x).sum() };
    assert!((momentum(t0) - momentum(t0 - 1e-9)).abs() < 1e-12);
    // Same-instant impacts are resolved one pair at a time (the sequential hypothesis), which
    // is not exactly symmetric: the middle ball drifts, but by far less than a ball's width.
    let fin = shot.final_states();
    assert!(fin[0].pos.x.abs() < 1e-3 * r, "{}", fin[0].pos.x);
}

#[test]
fn a_newtons_cradle_ends() {
    // A line of five touching balls hit end-on: the impacts at one instant must end.
    let p = Params::default();
    let r = p.ball_radius;
    let mut balls: Vec<Ball> = (0..5)
        .map(|k| resting(&format!("red{k}"), 2.0 * r * k as f64, 0.0, &p))
        .collect();
    balls.insert(0, rolling("cue", -0.2, 0.0, Vec3::new(2.0, 0.0, 0.0), &p));
    let s = setup(Table::open(), balls);
    let shot = run(&s);
    let fin = shot.final_states();
    // The far ball takes most of the momentum.
    assert!(fin[5].pos.x > fin[4].pos.x);
}

#[test]
fn the_break_off_rack_with_touching_reds() {
    let p = Params::default();
    let dims = Default::default();
    for speed in [1.0, 3.0, 6.0, 9.0] {
        let mut balls = snooker_engine::table::layout::break_off(&dims, p.ball_radius);
        // Full on the apex red: the hardest case for simultaneous contacts.
        let apex = balls.iter().find(|b| b.id == "red1").unwrap().state.pos;
        let start = balls[0].state.pos;
        let aim = (apex.y - start.y).atan2(apex.x - start.x);
        let cue = Cue {
            speed,
            aim,
            offset: [0.0, 0.0],
            elevation: 0.0,
        };
        balls[0].state = cue::strike(&balls[0].state, &cue, &p).unwrap().state;
        let s = setup(Table::snooker(&dims), balls);
        let shot = run(&s);
        // It must pass the pink (1 mm gap in front of the apex) without touching... or hit it:
        // the cue ball is aimed at the apex red, which is straight behind the pink.
        assert!(shot.events.iter().any(|e| e.kind == EventKind::BallBall));
    }
}

#[test]
fn a_ball_pressed_against_another_does_not_sink_into_it() {
    // At rest with heavy topspin, touching a red in front: its own friction drives it into the
    // red from zero relative speed (sustained contact).
    let p = Params::default();
    let r = p.ball_radius;
    let s = setup(
        Table::open(),
        vec![
            ball(
                "cue",
                Vec3::new(0.0, 0.0, r),
                Vec3::zeros(),
                Vec3::new(0.0, 80.0, 0.0),
            ),
            resting("red", 2.0 * r, 0.0, &p),
        ],
    );
    let shot = run(&s);
    assert!(shot.events.iter().any(|e| e.kind == EventKind::BallBall));
}

#[test]
fn frictionless_cloth_ends_with_an_error_not_a_hang() {
    // Bouncing across the table between the side cushions, far from any pocket.
    let mut s = setup(
        Table::snooker(&Default::default()),
        vec![rolling(
            "cue",
            1.0,
            0.5,
            Vec3::new(0.0, 1.0, 0.0),
            &Params::default(),
        )],
    );
    s.params.mu_roll = 0.0;
    s.params.mu_slide = 0.0;
    let opts = SimOptions {
        max_time: 60.0,
        ..SimOptions::default()
    };
    match simulate(&s, &opts) {
        Err(SimError::DidNotStop { max_time }) => assert_eq!(max_time, 60.0),
        other => panic!("expected DidNotStop, got {other:?}"),
    }
    // The open table never stops either: no events at all, still an error.
    s.table = Table::open();
    assert!(matches!(
        simulate(&s, &opts),
        Err(SimError::DidNotStop { .. })
    ));
}

#[test]
fn a_runaway_hits_the_event_cap_with_an_error() {
    let p = Params::default();
    let mut balls = snooker_engine::table::layout::break_off(&Default::default(), p.ball_radius);
    let cue = Cue {
        speed: 5.0,
        aim: 0.0,
        offset: [0.0, 0.0],
        elevation: 0.0,
    };
    balls[0].state = cue::strike(&balls[0].state, &cue, &p).unwrap().state;
    let s = setup(Table::snooker(&Default::default()), balls);
    let opts = SimOptions {
        max_events: 10,
        ..SimOptions::default()
    };
    assert!(matches!(
        simulate(&s, &opts),
        Err(SimError::TooManyEvents { limit: 10, .. })
    ));
}

#[test]
fn the_horizon_stops_a_shot_cleanly() {
    let p = Params::default();
    let s = setup(
        Table::open(),
        vec![rolling("cue", 0.0, 0.0, Vec3::new(2.0, 0.0, 0.0), &p)],
    );
    let opts = SimOptions {
        horizon: Some(1.0),
        ..SimOptions::default()
    };
    let shot = simulate(&s, &opts).unwrap();
    assert_eq!(shot.ending, snooker_engine::Ending::Horizon);
    assert_eq!(shot.duration, 1.0);
    assert!(shot.final_states()[0].motion == Motion::Rolling);
}

#[test]
fn the_horizon_ends_a_shot_whose_next_event_lies_beyond_it() {
    // Without rolling resistance the roll never ends, and the cushion is reached only after
    // the horizon: nothing is left to happen before it, which is not a runaway.
    let p = Params {
        mu_roll: 0.0,
        ..Params::default()
    };
    let mut s = setup(
        Table::snooker(&Default::default()),
        vec![rolling("cue", 1.0, 0.9, Vec3::new(0.5, 0.0, 0.0), &p)],
    );
    s.params = p;
    let opts = SimOptions {
        horizon: Some(1.0),
        ..SimOptions::default()
    };
    let shot = simulate(&s, &opts).unwrap();
    assert_eq!(shot.ending, snooker_engine::Ending::Horizon);
    assert_eq!(shot.duration, 1.0);
    assert!((shot.final_states()[0].pos.x - 1.5).abs() < 1e-12);
}
