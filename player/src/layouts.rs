//! The frames the player is measured on: the open table of the benchmarks (15 reds scattered
//! at random, the colours on their spots, the cue ball in hand).

use snooker_engine::BallKind;
use snooker_rules::{Frame, FrameState};

/// Reds scattered at random (seeded: [`Frame::open_table`], clear of the cushions, the
/// pockets, the spots and each other), the colours on their spots, reds on, player 0 to play
/// with the cue ball in hand.
pub fn open_table_in_hand(seed: u64) -> Frame {
    let open = Frame::open_table(15, seed);
    let balls = open
        .balls()
        .iter()
        .filter(|b| b.kind != BallKind::Cue)
        .cloned()
        .collect();
    let state = FrameState {
        ball_in_hand: true,
        ..*open.state()
    };
    Frame::new(
        "open-table",
        open.table().clone(),
        *open.params(),
        *open.models(),
        *open.options(),
        balls,
        state,
    )
    .expect("an open table with the cue ball in hand is a frame")
}
