//! The referee's verdict on one stroke, and what follows from it: the next frame, or the end
//! of the frame and its winner.

use crate::colour::Colour;
use crate::foul::Foul;
use crate::frame::Frame;
use crate::respot::Respot;
use crate::state::{FrameState, On, Player};
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

    /// The frame after a foul judged on this frame when the non-offender asks the offender to
    /// play again (WPBSA Section 3 Rule 3(b), Rule 11, Rule 13): the table as the stroke left
    /// it ([`Frame::next`]), the scores with the foul's points, the same ball on, the offender
    /// at the table (from hand if the cue ball is in hand), and no free ball (Rule 12: if the
    /// offender is asked to play again, the free ball call is void). `None` after a legal
    /// stroke, and after a foul on the last black, which ends the frame or, with the scores
    /// equal, starts the re-spotted black (Section 3 Rule 4), played by lot.
    pub fn play_again(&self, verdict: &Verdict) -> Option<Frame> {
        match verdict.next {
            Some(next) if self.foul_goes_on(verdict) => {
                let state = FrameState {
                    to_play: self.state().to_play,
                    nominated: None,
                    free_ball: false,
                    ..next
                };
                Some(self.with_parts(verdict.balls.clone(), state))
            }
            _ => None,
        }
    }

    /// The frame before a foul judged on this frame, put back for the offender to play the
    /// stroke again, as after a foul and a miss (WPBSA Section 3 Rule 14): the balls where
    /// they were, the same ball on (after a red, a colour of the striker's choice again: no
    /// nomination), the offender at the table, the scores with the foul's points. Whether the
    /// foul was a miss is the referee's judgement, not a program's (docs/rules.md): the caller
    /// decides. `None` where [`Frame::play_again`] is `None`.
    pub fn put_back(&self, verdict: &Verdict) -> Option<Frame> {
        self.foul_goes_on(verdict).then(|| {
            let state = FrameState {
                scores: verdict.scores,
                nominated: None,
                ..*self.state()
            };
            self.with_parts(self.balls().to_vec(), state)
        })
    }

    /// A foul that leaves the frame going on with the same ball on: not on the last black
    /// (which ends the frame, or with the scores equal starts the re-spotted black).
    fn foul_goes_on(&self, verdict: &Verdict) -> bool {
        verdict.foul.is_some()
            && verdict.next.is_some()
            && self.state().on != On::Closing(Colour::Black)
    }
}
