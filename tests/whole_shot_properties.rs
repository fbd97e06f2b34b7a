//! Whole-shot properties of our engine on random small racks and strikes: energy never
//! increases (beyond the micro-collision allowance), no two balls overlap at any event, every
//! ball ends at rest or pocketed, and the same setup gives the same shot.

use proptest::prelude::*;
use snooker_engine::cue::{self, Cue};
use snooker_engine::detect::{SKIN, VERIFY_TOL};
use snooker_engine::impact::MIN_SEPARATION;
use snooker_engine::{
    Ball, BallKind, BallState, EventKind, Models, Motion, Params, Setup, Shot, SimOptions, Table,
    simulate,
};

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

/// Total energy of the balls whose states are `states`.
fn energy(states: &[BallState], p: &Params) -> f64 {
    states
        .iter()
        .map(|s| s.energy(p.ball_mass, p.inertia(), p.ball_radius, p.g))
        .sum()
}

/// The largest energy an event may add: an impact slower than MIN_SEPARATION leaves at
/// MIN_SEPARATION (engine/src/impact/mod.rs), gaining at most 1/2 m_eff MIN_SEPARATION^2, with
/// m_eff = M/2 for two equal balls and M against a cushion (fixed). Other events add nothing.
fn allowance(kind: EventKind, p: &Params) -> f64 {
    let m_eff = match kind {
        EventKind::BallBall => p.ball_mass / 2.0,
        EventKind::BallCushion => p.ball_mass,
        _ => 0.0,
    };
    0.5 * m_eff * MIN_SEPARATION * MIN_SEPARATION
}

/// Every ball's state just after event `k` (events at the same instant included up to `k`).
fn after_event(shot: &Shot, k: usize) -> Vec<BallState> {
    let e = &shot.events[k];
    let mut states: Vec<BallState> = shot
        .tracks
        .iter()
        .map(|t| t.state_at(e.t, &shot.params))
        .collect();
    // Later events at the same instant are already in `state_at`: undo them, latest first.
    for later in shot.events[k + 1..]
        .iter()
        .take_while(|l| l.t == e.t)
        .collect::<Vec<_>>()
        .into_iter()
        .rev()
    {
        for (&b, s) in later.balls.iter().zip(&later.before) {
            states[b] = *s;
        }
    }
    states
}

fn check_energy(shot: &Shot) -> Result<(), TestCaseError> {
    let p = &shot.params;
    // Rounding allowance on sums of a few joules: relative 1e-12.
    let round = |e: f64| 1e-12 * e.abs().max(1e-3);
    let mut last = energy(
        &shot
            .tracks
            .iter()
            .map(|t| t.segments[0].state)
            .collect::<Vec<_>>(),
        p,
    );
    for (k, e) in shot.events.iter().enumerate() {
        let after = after_event(shot, k);
        let mut before = after.clone();
        for (&b, s) in e.balls.iter().zip(&e.before) {
            before[b] = *s;
        }
        let (eb, ea) = (energy(&before, p), energy(&after, p));
        // Between events only friction acts.
        prop_assert!(
            eb <= last + round(last),
            "energy rose between events to {k}: {last} -> {eb}"
        );
        prop_assert!(
            ea <= eb + allowance(e.kind, p) + round(eb),
            "event {k} ({:?}) raised the energy by {} J",
            e.kind,
            ea - eb
        );
        last = ea;
    }
    Ok(())
}

fn check_no_overlap(shot: &Shot) -> Result<(), TestCaseError> {
    let r = shot.params.ball_radius;
    for (k, e) in shot.events.iter().enumerate() {
        let states = after_event(shot, k);
        for (i, a) in states.iter().enumerate() {
            for (j, b) in states.iter().enumerate().skip(i + 1) {
                if a.motion == Motion::Pocketed || b.motion == Motion::Pocketed {
                    continue;
                }
                let overlap = 2.0 * r - (a.pos - b.pos).norm();
                // Contacts are found one skin inside 2R and verified to VERIFY_TOL.
                prop_assert!(
                    overlap <= SKIN + VERIFY_TOL,
                    "balls {i} and {j} overlap by {overlap:e} m after event {k} at t = {}",
                    e.t
                );
            }
        }
    }
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
        check_energy(&shot)?;
        check_no_overlap(&shot)?;
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
