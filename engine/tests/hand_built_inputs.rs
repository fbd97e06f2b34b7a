//! What a Rust caller builds by hand, not through a scene file: limits, a table and a strike's
//! parameters the readers would have refused. The engine checks them itself, naming the field
//! at fault, rather than letting a NaN or a degenerate shape into a shot (the standard: no NaN
//! or infinity ever leaves the engine).

mod common;

use snooker_engine::cue::{self, Cue};
use snooker_engine::{BallState, Motion, Params, SimError, SimOptions, Table, Vec3, simulate};

/// A rolling cue ball on the full-size table, a shot that ends well inside any sane limit.
fn rolling_on_snooker() -> snooker_engine::Setup {
    let p = Params::default();
    let vel = Vec3::new(0.8, 0.3, 0.0);
    let state = BallState {
        pos: Vec3::new(1.0, 0.9, p.ball_radius),
        vel,
        spin: Vec3::z().cross(&vel) / p.ball_radius,
        motion: Motion::Stationary,
    };
    let mut s = common::one_ball_setup(state, p);
    s.table = Table::snooker(&Default::default());
    s
}

/// The field `simulate` blames, with its reason, or a panic naming what it did instead.
fn refused(setup: &snooker_engine::Setup, opts: &SimOptions) -> (String, String) {
    match simulate(setup, opts) {
        Err(SimError::Setup(e)) => {
            assert_eq!(e.ball, None, "{e}");
            (e.field, e.reason)
        }
        other => panic!("expected a refused setup, got {other:?}"),
    }
}

#[test]
fn limits_that_are_not_a_number_of_seconds_are_refused() {
    let s = rolling_on_snooker();
    let d = SimOptions::default();
    let cases = [
        (
            SimOptions {
                max_time: f64::NAN,
                ..d
            },
            "options.max_time",
        ),
        (SimOptions { max_time: 0.0, ..d }, "options.max_time"),
        (
            SimOptions {
                max_time: f64::INFINITY,
                ..d
            },
            "options.max_time",
        ),
        (
            SimOptions {
                horizon: Some(f64::NAN),
                ..d
            },
            "options.horizon",
        ),
        (
            SimOptions {
                horizon: Some(-1.0),
                ..d
            },
            "options.horizon",
        ),
        (SimOptions { max_events: 0, ..d }, "options.max_events"),
    ];
    for (opts, field) in cases {
        let (got, reason) = refused(&s, &opts);
        assert_eq!(got, field, "{opts:?}: {reason}");
    }
    // The edges that are limits: a horizon at the start stops the shot there.
    let shot = simulate(
        &s,
        &SimOptions {
            horizon: Some(0.0),
            ..d
        },
    )
    .unwrap();
    assert_eq!(shot.duration, 0.0);
    assert!(simulate(&s, &d).is_ok());
}

#[test]
fn a_table_put_together_wrongly_is_refused_naming_the_part() {
    let s = rolling_on_snooker();
    let opts = SimOptions::default();
    assert_eq!(s.table.geometry_error(), None);
    assert_eq!(Table::open().geometry_error(), None);
    type Break = fn(&mut Table);
    let cases: [(Break, &str); 12] = [
        (|t| t.length = f64::NAN, "table.length"),
        (|t| t.width = 0.0, "table.width"),
        (
            |t| t.cushions[0].start.x = f64::NAN,
            "table.cushions[0].start",
        ),
        (|t| t.cushions[1].end.z = 0.01, "table.cushions[1].end"),
        (
            |t| t.cushions[2].end = t.cushions[2].start,
            "table.cushions[2].end",
        ),
        (|t| t.cushions[0].normal *= 2.0, "table.cushions[0].normal"),
        (
            |t| t.cushions[0].normal = t.cushions[0].direction(),
            "table.cushions[0].normal",
        ),
        (|t| t.jaws[3].radius = -0.01, "table.jaws[3].radius"),
        (|t| t.jaws[0].centre.y = 1e12, "table.jaws[0].centre"),
        (
            |t| t.pockets[5].radius = f64::NAN,
            "table.pockets[5].radius",
        ),
        (
            |t| t.pockets[2].mouth_width = 0.0,
            "table.pockets[2].mouth_width",
        ),
        (
            |t| t.pockets[1].mouth.x = f64::INFINITY,
            "table.pockets[1].mouth",
        ),
    ];
    for (spoil, field) in cases {
        let mut bad = s.clone();
        spoil(&mut bad.table);
        let (got, reason) = refused(&bad, &opts);
        assert_eq!(got, field, "{reason}");
    }
    // The open table has no sides: zero is its length, not a fault.
    let mut open = s.clone();
    open.table = Table::open();
    assert!(simulate(&open, &opts).is_ok());
}

#[test]
fn a_strike_with_parameters_or_a_ball_out_of_range_is_refused() {
    let p = Params::default();
    let ball = rolling_on_snooker().balls[0].state;
    let c = Cue {
        speed: 2.0,
        aim: 0.3,
        offset: [0.0, 0.01],
        elevation: 0.1,
    };
    assert!(cue::strike(&ball, &c, &p).is_ok());
    let mut q = p;
    q.cue_mass = f64::NAN;
    let e = cue::strike(&ball, &c, &q).unwrap_err();
    assert_eq!(e.key, "params", "{e}");
    assert!(e.reason.starts_with("cue_mass:"), "{e}");
    let mut q = p;
    q.ball_radius = 0.0;
    assert_eq!(cue::strike(&ball, &c, &q).unwrap_err().key, "params");
    let mut nan_ball = ball;
    nan_ball.spin.x = f64::NAN;
    assert_eq!(cue::strike(&nan_ball, &c, &p).unwrap_err().key, "ball");
}
