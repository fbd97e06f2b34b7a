//! An agent chooses the stroke for a frame: the player ([`crate::Player`]) or the greedy
//! baseline ([`crate::Greedy`]).

use crate::decision::Decision;
use snooker_planner::Noise;
use snooker_rules::Frame;

/// What an agent knows beside the frame: the execution noise it will be played with, the
/// run's seed and the stroke's number (every random draw of a decision is seeded from them),
/// and its budget.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Context {
    /// The execution noise.
    pub noise: Noise,
    /// The run's seed.
    pub seed: u64,
    /// The stroke's number in the run (from 1).
    pub stroke: u64,
    /// The search's budget, in simulated shots.
    pub effort: u64,
}

/// Why no stroke could be chosen.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ChooseError {
    /// The frame cannot be played (a key at fault).
    #[error(transparent)]
    Frame(#[from] snooker_rules::FrameError),
    /// No strike at all can be played from this frame (every strike tried was refused).
    #[error("no strike can be played from this frame")]
    NoStrike,
}

/// Something that chooses strokes.
pub trait Agent: Sync {
    /// Its name (`player`, `greedy`).
    fn name(&self) -> &'static str;

    /// The stroke for `frame` (the cue ball placed and the nomination made by the decision).
    fn choose(&self, frame: &Frame, ctx: &Context) -> Result<Decision, ChooseError>;
}
