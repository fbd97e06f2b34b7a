//! Shared helpers of the engine's integration tests.
#![allow(dead_code)]

use snooker_engine::audit::{audit, report};
use snooker_engine::{Ball, BallKind, BallState, Ending, Models, Params, Setup, Shot, Table};

/// One cue ball in `state` on the open table with parameters `p`.
pub fn one_ball_setup(state: BallState, p: Params) -> Setup {
    Setup {
        table: Table::open(),
        params: p,
        models: Models::default(),
        balls: vec![Ball {
            id: "cue".into(),
            kind: BallKind::Cue,
            state,
        }],
    }
}

/// Asserts the invariants every finished shot must satisfy ([`snooker_engine::audit`]): it
/// ended with every ball at rest or pocketed, and broke none.
pub fn check_shot(setup: &Setup, shot: &Shot) {
    assert_eq!(shot.ending, Ending::AtRest, "the shot did not end at rest");
    if let Some(broken) = report(&audit(setup, shot)) {
        panic!("{broken}");
    }
}
