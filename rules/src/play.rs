//! A stroke played through: the strike simulated by the engine from the frame, then judged.

use crate::error::{FrameError, JudgeError};
use crate::frame::Frame;
use crate::verdict::Verdict;
use snooker_engine::cue::Cue;
use snooker_engine::{Shot, SimError};

/// A stroke played: the simulated shot and the referee's verdict.
#[derive(Clone, Debug, PartialEq)]
pub struct Stroke {
    /// The shot.
    pub shot: Shot,
    /// The verdict.
    pub verdict: Verdict,
}

/// Why a stroke could not be played.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PlayError {
    /// The frame is not ready or the strike is refused: the key at fault.
    #[error(transparent)]
    Frame(#[from] FrameError),
    /// The engine could not simulate the shot to its end.
    #[error("{0}")]
    Sim(#[from] SimError),
    /// The shot could not be judged.
    #[error(transparent)]
    Judge(#[from] JudgeError),
}

impl Frame {
    /// Plays `strike` on the cue ball: simulates it ([`Frame::setup`], the frame's limits) and
    /// judges it ([`Frame::judge`]).
    pub fn play(&self, strike: &Cue) -> Result<Stroke, PlayError> {
        let setup = self.setup(strike)?;
        let shot = snooker_engine::simulate(&setup, self.options())?;
        let verdict = self.judge(&shot)?;
        Ok(Stroke { shot, verdict })
    }
}
