//! Rerun recordings, made by whoever embeds the server: the `snooker` command line hands
//! `snooker serve` its own exporter (`src/record/`, the one `snooker simulate`
//! uses), so that this crate neither depends on the command line's crate nor builds Rerun's
//! writer, and a program embedding the lab without recordings does without them.

use crate::error::ApiError;
use crate::limits::Limits;
use snooker_engine::Shot;
use snooker_scene::Scene;

/// Makes the Rerun recording (`.rrd` bytes) of a simulated shot.
pub trait Recorder: Send + Sync {
    /// The recording of `shot`, simulated from `scene`, as `snooker simulate` records it with
    /// `--record-rate rate` (Hz; every event instant is sampled as well); the error says why
    /// it could not be made.
    fn shot(&self, scene: &Scene, shot: &Shot, rate: f64) -> Result<Vec<u8>, String>;
}

/// The rate a recording of `shot` is made at: `wanted` (Hz), lowered so that the recording
/// holds at most [`Limits::recording_samples`] ball samples (every ball at every instant: the
/// grid, the end, two instants per event). A shot whose events alone would hold more is
/// refused (422): its result can still be downloaded. Before this bound a long shot (600 s of
/// frictionless cloth, four balls) made a 100 MB answer and took 1.5 GB to make it.
pub fn rate(shot: &Shot, wanted: f64, limits: &Limits) -> Result<f64, ApiError> {
    let balls = shot.tracks.len().max(1) as f64;
    let per_ball = limits.recording_samples as f64 / balls;
    let fixed = 2.0 + 2.0 * shot.resolved_events() as f64;
    if fixed > per_ball {
        return Err(ApiError::unfinished(
            crate::input::SCENE,
            format!(
                "the recording of this shot would hold {} ball samples at its events alone \
                 (limit {}); download its result instead",
                (fixed * balls) as u64,
                limits.recording_samples
            ),
        ));
    }
    let room = per_ball - fixed;
    Ok(if shot.duration * wanted > room {
        room / shot.duration
    } else {
        wanted
    })
}
