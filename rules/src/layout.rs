//! Standard frames: the break-off (the rack, the colours on their spots, the cue ball in hand
//! in the D: WPBSA Section 3 Rule 2 "Position of Balls"), and an open table (reds scattered
//! at random, seeded, the colours on their spots) for play and training from varied positions.

use crate::colour::Colour;
use crate::frame::Frame;
use crate::respot;
use crate::state::{FrameState, On};
use snooker_engine::rng::Rng;
use snooker_engine::table::layout;
use snooker_engine::{Ball, BallKind, BallState, Models, Params, SimOptions, SnookerDims, Table};

/// Gap kept between balls scattered at random, m (so that no two start touching).
pub const SCATTER_GAP: f64 = 0.002;

impl Frame {
    /// The start of a frame: the break-off layout of the engine (15 reds in the triangle, the
    /// colours on their spots), the cue ball in hand placed in the D between the brown and
    /// yellow spots, reds on, player 0 to break off.
    pub fn break_off() -> Frame {
        let dims = SnookerDims::default();
        let params = Params::default();
        let balls = layout::break_off(&dims, params.ball_radius);
        Frame::new(
            "break-off",
            Table::snooker(&dims),
            params,
            Models::default(),
            SimOptions::default(),
            balls,
            FrameState::start(0),
        )
        .expect("the break-off layout is a frame")
    }

    /// An open table: `reds` reds (at most 15) at uniformly random places on the cloth and the
    /// cue ball likewise, clear of the cushions, the pockets, the colours on their spots and
    /// each other by [`SCATTER_GAP`]; reds on (with no reds: the yellow), player 0 to play, the
    /// cue ball not in hand. The same `seed` gives the same frame.
    pub fn open_table(reds: usize, seed: u64) -> Frame {
        let dims = SnookerDims::default();
        let params = Params::default();
        let table = Table::snooker(&dims);
        let r = params.ball_radius;
        let contact = params.cushion_contact_distance();
        // xorshift needs a non-zero state: mix the seed (splitmix64's finaliser).
        let mut z = seed.wrapping_add(0x9e37_79b9_7f4a_7c15);
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        let mut rng = Rng((z ^ (z >> 31)).max(1));
        let mut balls: Vec<Ball> = Colour::ALL
            .iter()
            .map(|&c| {
                let p = respot::spot(&dims, c);
                Ball {
                    id: c.name().into(),
                    kind: c.kind(),
                    state: BallState::at_rest(p.x, p.y, r),
                }
            })
            .collect();
        let margin = contact + SCATTER_GAP;
        let ids = (1..=reds.min(15))
            .map(|n| (format!("red{n}"), BallKind::Red))
            .chain(std::iter::once(("cue".to_string(), BallKind::Cue)));
        for (id, kind) in ids {
            loop {
                let x = rng.uniform(margin, dims.length - margin);
                let y = rng.uniform(margin, dims.width - margin);
                let p = snooker_engine::Vec3::new(x, y, 0.0);
                let clear = balls
                    .iter()
                    .all(|b| (b.state.pos.xy() - p.xy()).norm() >= 2.0 * r + SCATTER_GAP);
                let placeable = table.placement_error(p, contact + SCATTER_GAP).is_none();
                if clear && placeable {
                    balls.push(Ball {
                        id,
                        kind,
                        state: BallState::at_rest(x, y, r),
                    });
                    break;
                }
            }
        }
        let on = if reds == 0 {
            On::Closing(Colour::Yellow)
        } else {
            On::Red
        };
        let state = FrameState {
            on,
            ball_in_hand: false,
            ..FrameState::start(0)
        };
        Frame::new(
            "open-table",
            table,
            params,
            Models::default(),
            SimOptions::default(),
            balls,
            state,
        )
        .expect("an open table is a frame")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn standard_frames_are_frames_and_the_seed_decides() {
        let b = Frame::break_off();
        assert_eq!(b.balls().len(), 22);
        assert!(b.state().ball_in_hand);
        let a = Frame::open_table(10, 7);
        assert_eq!(a.balls().len(), 17);
        assert_eq!(a, Frame::open_table(10, 7));
        assert_ne!(a, Frame::open_table(10, 8));
        assert_eq!(
            Frame::open_table(0, 1).state().on,
            On::Closing(Colour::Yellow)
        );
        // The engine accepts it: on the cloth, nothing overlapping.
        let setup = snooker_engine::Setup {
            table: a.table().clone(),
            params: *a.params(),
            models: *a.models(),
            balls: a.balls().to_vec(),
        };
        setup.validate().unwrap();
    }
}
