//! What a stroke's result is worth, in points, to the player who played it: the points scored,
//! less the foul's points given away, and the position left: the player's own next stroke if
//! they stay at the table ([`Valuer::position`]), the opponent's (counted against) if not.

use crate::value::Valuer;
use snooker_rules::{Frame, Next, Verdict};

/// Points a won frame is worth beyond its strokes' points (and a lost one costs).
pub const FRAME_WON: f64 = 20.0;

/// A stroke's result, valued.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome {
    /// Points, to the player who played the stroke.
    pub value: f64,
    /// The stroke was legal and potted the ball the stroke was meant to pot.
    pub potted: bool,
    /// The stroke was a foul.
    pub foul: bool,
}

/// The value of `verdict` (the referee's verdict on a stroke played from `frame`) to the
/// player who played it; `pot` is the id of the ball the stroke was meant to pot, if any.
pub fn outcome(frame: &Frame, verdict: &Verdict, valuer: &Valuer, pot: Option<&str>) -> Outcome {
    let player = frame.state().to_play;
    let gain = verdict.points as f64 - verdict.foul_points() as f64;
    let value = match frame.next(verdict) {
        Next::Over { winner, .. } => {
            gain + if winner == player {
                FRAME_WON
            } else {
                -FRAME_WON
            }
        }
        Next::Play(next) => {
            let v = valuer.position(&next);
            if next.state().to_play == player {
                gain + v
            } else {
                gain - v
            }
        }
    };
    Outcome {
        value,
        potted: verdict.legal() && pot.is_some_and(|id| verdict.potted.iter().any(|p| p == id)),
        foul: !verdict.legal(),
    }
}
