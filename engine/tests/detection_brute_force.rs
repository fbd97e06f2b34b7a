//! Event detection against brute force: random racks and shots, every ball sampled on a fine
//! time grid (0.5 ms, plus just before and after every event): no two balls ever overlap by
//! more than 1 micrometre, no ball leaves the table except into a pocket, events are in time
//! order and every ball ends at rest or pocketed.

mod common;

use proptest::prelude::*;
use snooker_engine::cue::{self, Cue};
use snooker_engine::table::layout;
use snooker_engine::{
    Ball, BallKind, BallState, Models, Params, Setup, SimOptions, Table, Vec3, motion, simulate,
};

fn snooker_setup(balls: Vec<Ball>) -> Setup {
    Setup {
        table: Table::snooker(&Default::default()),
        params: Params::default(),
        models: Models::default(),
        balls,
    }
}

/// Random non-overlapping balls (possibly touching in clusters) and a strike on the first.
fn rack() -> impl Strategy<Value = (Vec<(f64, f64)>, Cue)> {
    let pos = (0.05f64..3.52, 0.05f64..1.73);
    (
        prop::collection::vec(pos, 2..16),
        0.3f64..8.0,
        -3.2f64..3.2,
        -0.01f64..0.01,
        -0.01f64..0.01,
        0.0f64..0.6,
    )
        .prop_map(|(pts, speed, aim, side, height, elevation)| {
            (
                pts,
                Cue {
                    speed,
                    aim,
                    offset: [side, height],
                    elevation,
                },
            )
        })
}

fn place(points: &[(f64, f64)], p: &Params, table: &Table) -> Vec<Ball> {
    let r = p.ball_radius;
    let mut balls: Vec<Ball> = Vec::new();
    for &(x, y) in points {
        let mut s = BallState::at_rest(x, y, r);
        // Snap onto a neighbour when close, to make touching clusters.
        if let Some(o) = balls
            .iter()
            .find(|b| (b.state.pos - s.pos).norm() < 3.0 * r)
        {
            let d = (s.pos - o.state.pos).normalize();
            s.pos = o.state.pos + 2.0 * r * d;
        }
        let clear = balls
            .iter()
            .all(|b| (b.state.pos - s.pos).norm() >= 2.0 * r - 1e-12);
        if clear
            && table
                .placement_error(s.pos, p.cushion_contact_distance())
                .is_none()
        {
            let id = if balls.is_empty() {
                "cue".to_string()
            } else {
                format!("red{}", balls.len())
            };
            balls.push(Ball {
                kind: BallKind::from_id(&id),
                id,
                state: s,
            });
        }
    }
    balls
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, .. ProptestConfig::default() })]

    #[test]
    fn random_racks_never_overlap_or_escape((points, strike) in rack()) {
        let mut setup = snooker_setup(Vec::new());
        setup.balls = place(&points, &setup.params, &setup.table);
        prop_assume!(setup.balls.len() >= 2);
        if let Ok(s) = cue::strike(&setup.balls[0].state, &strike, &setup.params) {
            setup.balls[0].state = s.state;
            let shot = simulate(&setup, &SimOptions::default()).expect("simulation failed");
            common::check_shot(&setup, &shot);
        }
    }
}

#[test]
fn break_offs_at_many_angles() {
    let dims = Default::default();
    let p = Params::default();
    for k in 0..24 {
        let mut balls = layout::break_off(&dims, p.ball_radius);
        let cue = Cue {
            speed: 4.0 + 0.2 * k as f64,
            aim: 0.02 * (k as f64 - 12.0),
            offset: [0.004, -0.003],
            elevation: 0.1,
        };
        balls[0].state = cue::strike(&balls[0].state, &cue, &p).unwrap().state;
        let setup = snooker_setup(balls);
        let shot = simulate(&setup, &SimOptions::default()).expect("simulation failed");
        common::check_shot(&setup, &shot);
    }
}

fn vec3() -> impl Strategy<Value = Vec3> {
    (-5.0f64..5.0, -5.0f64..5.0, -1.0f64..1.0).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, .. ProptestConfig::default() })]

    /// The bound the contact searches are culled by (`Path::clearance`) never exceeds the
    /// distance from the origin found by sampling the path finely: a culled search could not
    /// have found a contact.
    #[test]
    fn culling_bound_is_below_the_sampled_distance(
        c in vec3(), b in vec3(), a in vec3(), window in 1e-6f64..2.0,
    ) {
        let path = motion::Path { c, b, a };
        let sampled = (0..=20_000)
            .map(|k| path.at(window * k as f64 / 20_000.0).norm())
            .fold(f64::INFINITY, f64::min);
        let bound = path.clearance(window);
        prop_assert!(bound <= sampled + 1e-12 * path.size(window), "{bound} > {sampled}");
    }
}
