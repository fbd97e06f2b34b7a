//! Rerun recordings, made by whoever embeds the server: the `snooker` command line hands
//! `snooker serve` its own exporter (`src/record/`, the one `snooker simulate`
//! uses), so that this crate neither depends on the command line's crate nor builds Rerun's
//! writer, and a program embedding the lab without recordings does without them.

use snooker_engine::Shot;
use snooker_scene::Scene;

/// Makes the Rerun recording (`.rrd` bytes) of a simulated shot.
pub trait Recorder: Send + Sync {
    /// The recording of `shot`, simulated from `scene`, as `snooker simulate` records it; the
    /// error says why it could not be made.
    fn shot(&self, scene: &Scene, shot: &Shot) -> Result<Vec<u8>, String>;
}
