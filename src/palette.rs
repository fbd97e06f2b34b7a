//! Colours of the balls, shared by the recordings and the plots (the engine knows a ball's
//! kind, not how it looks).

use snooker_engine::BallKind;

/// sRGB colour of a ball of kind `k`.
pub fn ball(k: BallKind) -> [u8; 3] {
    match k {
        BallKind::Cue => [245, 245, 235],
        BallKind::Red => [200, 20, 20],
        BallKind::Yellow => [240, 210, 20],
        BallKind::Green => [20, 120, 50],
        BallKind::Brown => [120, 70, 30],
        BallKind::Blue => [30, 70, 200],
        BallKind::Pink => [240, 130, 170],
        BallKind::Black => [15, 15, 15],
        BallKind::Other => [150, 150, 150],
    }
}
