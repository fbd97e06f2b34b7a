//! Shots that once failed inside an impact, kept as regressions: a valid shot must always
//! simulate.

use snooker_engine::cue::{self, Cue};
use snooker_engine::{
    Ball, BallKind, BallState, Models, Params, Setup, SimOptions, SnookerDims, Table, simulate,
};

/// The cue ball frozen against two touching reds (a fuzz run's minimal scene), struck at
/// `speed` m/s along `aim` rad, 0.11 rad of elevation, centre ball.
fn frozen_against_two_reds(speed: f64, aim: f64) -> Setup {
    let p = Params::default();
    let r = p.ball_radius;
    let ball = |id: &str, x: f64, y: f64| Ball {
        id: id.into(),
        kind: BallKind::from_id(id),
        state: BallState::at_rest(x, y, r),
    };
    let mut balls = vec![
        ball("cue", 1.0, 1.0),
        ball("red1", 1.013562117963372, 1.050614513297547),
        ball("red2", 0.962947604665825, 1.037052395334175),
    ];
    let strike = Cue {
        speed,
        aim,
        offset: [0.0, 0.0],
        elevation: 0.11,
    };
    balls[0].state = cue::strike(&balls[0].state, &strike, &p).unwrap().state;
    Setup {
        table: Table::snooker(&SnookerDims::default()),
        params: p,
        models: Models::default(),
        balls,
    }
}

#[test]
fn a_cue_ball_frozen_against_two_touching_reds_simulates() {
    // Failed with "more than 200 phases" in a ball-ball impact.
    let setup = frozen_against_two_reds(2.0, 2.5709);
    if let Err(e) = simulate(&setup, &SimOptions::default()) {
        panic!("{e}");
    }
}

#[test]
fn every_aim_and_speed_of_the_frozen_cluster_simulates() {
    // The failing window: aims scattered over 1.7 degrees about 2.5709 rad, at 1, 2, 5 and
    // 15 m/s.
    let mut failures = Vec::new();
    for speed in [1.0, 2.0, 5.0, 15.0] {
        for i in 0..=40 {
            let aim = 2.5709 + (i as f64 / 40.0 - 0.5) * 2.0f64.to_radians();
            if let Err(e) = simulate(&frozen_against_two_reds(speed, aim), &SimOptions::default()) {
                failures.push(format!("{speed} m/s, aim {aim}: {e}"));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
