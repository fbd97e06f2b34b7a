//! Whole-shot properties of our engine on random small racks and strikes: energy never
//! increases (beyond the micro-collision allowance), no two balls overlap at any event, every
//! ball ends at rest or pocketed, and the same setup gives the same shot.

use proptest::prelude::*;
use snooker_engine::audit;
use snooker_engine::cue::{self, Cue};
use snooker_engine::{
    Ball, BallKind, BallState, Models, Motion, Params, Setup, Shot, SimOptions, Table, simulate,
};
use snooker_engine::{SKIN, VERIFY_TOL};

/// Grid cells (columns x rows) over the playing area in which balls are placed, one per cell at
/// most, each cell wide enough for a ball anywhere in it never to overlap a neighbour's.
const COLS: usize = 12;
const ROWS: usize = 6;

/// A rack: distinct cells with an offset inside each, and a strike on the first ball.
fn rack() -> impl Strategy<Value = (Vec<(usize, f64, f64)>, Cue)> {
    (
        prop::collection::btree_set(0..COLS * ROWS, 2..12),
        prop::collection::vec((0.0f64..1.0, 0.0f64..1.0), 12),
        0.3f64..6.0,
        -3.2f64..3.2,
        (-0.01f64..0.01, -0.01f64..0.01),
        0.0f64..0.5,
    )
        .prop_map(|(cells, offsets, speed, aim, (side, height), elevation)| {
            let balls = cells
                .into_iter()
                .zip(offsets)
                .map(|(c, (u, v))| (c, u, v))
                .collect();
            let cue = Cue {
                speed,
                aim,
                offset: [side, height],
                elevation,
            };
            (balls, cue)
        })
}

/// The balls of a rack on the snooker table: cell c at column c % COLS, row c / COLS, the ball
/// placed at (u, v) within the cell's inner part, which keeps 2R between neighbours.
fn setup(cells: &[(usize, f64, f64)]) -> Setup {
    let table = Table::snooker(&Default::default());
    let p = Params::default();
    let r = p.ball_radius;
    let margin = 0.12; // clear of the cushions and the pocket mouths
    let (w, h) = (
        (table.length - 2.0 * margin) / COLS as f64,
        (table.width - 2.0 * margin) / ROWS as f64,
    );
    let balls = cells
        .iter()
        .enumerate()
        .map(|(i, &(c, u, v))| {
            let x = margin + (c % COLS) as f64 * w + r + u * (w - 2.0 * r);
            let y = margin + (c / COLS) as f64 * h + r + v * (h - 2.0 * r);
            let id = if i == 0 {
                "cue".to_string()
            } else {
                format!("red{i}")
            };
            Ball {
                kind: BallKind::from_id(&id),
                id,
                state: BallState::at_rest(x, y, r),
            }
        })
        .collect();
    Setup {
        table,
        params: p,
        models: Models::default(),
        balls,
    }
}

/// The invariants at every event ([`snooker_engine::audit::events`]), with contacts found one
/// skin inside 2R and verified to VERIFY_TOL: no overlap deeper than their sum.
fn check_events(shot: &Shot) -> Result<(), TestCaseError> {
    let broken = audit::report(&audit::events(shot, SKIN + VERIFY_TOL));
    prop_assert!(broken.is_none(), "{}", broken.unwrap_or_default());
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, .. ProptestConfig::default() })]

    #[test]
    fn whole_shots_keep_the_laws((cells, strike) in rack()) {
        let mut setup = setup(&cells);
        let Ok(s) = cue::strike(&setup.balls[0].state, &strike, &setup.params) else {
            // A miscue is not a shot.
            return Ok(());
        };
        setup.balls[0].state = s.state;
        let shot = simulate(&setup, &SimOptions::default()).expect("simulation failed");
        check_events(&shot)?;
        for (t, s) in shot.tracks.iter().zip(shot.final_states()) {
            prop_assert!(
                matches!(s.motion, Motion::Stationary | Motion::Pocketed),
                "{} ends {:?}", t.id, s.motion
            );
        }
        let again = simulate(&setup, &SimOptions::default()).expect("simulation failed");
        prop_assert!(again == shot, "the same setup gave a different shot");
    }
}
