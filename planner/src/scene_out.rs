//! The scene with the planned strike as its `[cue]` table: `snooker simulate` on it replays
//! the planned shot to the bit (every number is written so that it reads back exactly).

use crate::StrikeSpec;
use snooker_scene::write::{WriteError, with_cue};

/// `scene_text` with its `[cue]` replaced by `strike` ([`with_cue`]).
pub fn with_strike(scene_text: &str, strike: &StrikeSpec) -> Result<String, WriteError> {
    with_cue(scene_text, &strike.ball, &strike.cue())
}
