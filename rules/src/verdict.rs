//! The referee's verdict on one stroke, and what follows from it: the next frame, or the end
//! of the frame and its winner.

use crate::foul::Foul;
use crate::frame::Frame;
use crate::respot::Respot;
use crate::state::{FrameState, Player};
use snooker_engine::Ball;

/// The referee's verdict on a stroke.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdict {
    /// The foul, if the stroke was one.
    pub foul: Option<Foul>,
    /// The ball the cue ball hit first (with several at the same instant, the one not on if
    /// any, else the first listed); `None` when it hit nothing.
    pub first_hit: Option<String>,
    /// The object balls potted, in time order (never the cue ball).
    pub potted: Vec<String>,
    /// The cue ball went into a pocket.
    pub cue_ball_potted: bool,
    /// The balls forced off the table, in time order (the cue ball included).
    pub off_table: Vec<String>,
    /// Points scored by the player at the table.
    pub points: u32,
    /// The scores after the stroke (foul points to the opponent).
    pub scores: [u32; 2],
    /// The state of the next stroke; `None` when the frame is over.
    pub next: Option<FrameState>,
    /// The colours put back on the table, in the order placed (highest value first), by id.
    pub respotted: Vec<(String, Respot)>,
    /// The winner, when the frame is over.
    pub winner: Option<Player>,
    /// The balls of the next frame: where the shot left them (at rest; potted balls and
    /// balls off the table gone; the cue ball gone when in hand), the respotted colours on
    /// their spots, in the frame's order.
    pub balls: Vec<Ball>,
}

impl Verdict {
    /// True when the stroke was no foul.
    pub fn legal(&self) -> bool {
        self.foul.is_none()
    }

    /// True when the stroke ended the frame.
    pub fn frame_over(&self) -> bool {
        self.next.is_none()
    }

    /// Points of the foul, to the opponent (0 for a legal stroke).
    pub fn foul_points(&self) -> u32 {
        self.foul.as_ref().map_or(0, |f| f.points)
    }
}

/// What follows a stroke.
#[derive(Clone, Debug, PartialEq)]
pub enum Next {
    /// The frame goes on from this frame.
    Play(Box<Frame>),
    /// The frame is over.
    Over {
        /// The winner.
        winner: Player,
        /// The final scores.
        scores: [u32; 2],
    },
}

impl Frame {
    /// The frame after a stroke judged by [`Frame::judge`] on this frame: the verdict's balls
    /// and next state, or the end of the frame.
    pub fn next(&self, verdict: &Verdict) -> Next {
        match verdict.next {
            Some(state) => Next::Play(Box::new(self.with_parts(verdict.balls.clone(), state))),
            None => Next::Over {
                winner: verdict.winner.unwrap_or(0),
                scores: verdict.scores,
            },
        }
    }
}
