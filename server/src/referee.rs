//! A stroke of a frame played by hand: the frame's strike simulated by the engine and judged
//! by the rules crate, as `snooker referee` does: the referee's result (formats.md, "Referee
//! result", without `shot`), the shot's paths, and the frame that follows.

use crate::error::ApiError;
use crate::input::{self, FRAME};
use crate::limits::Limits;
use crate::position::{self, Position};
use crate::shot::{self, ShotView};
use serde::Serialize;
use serde_json::Value;
use snooker_rules::Next;
use snooker_scene::result::ShotRecord;

/// A stroke judged.
#[derive(Debug, Clone, Serialize)]
pub struct StrokeView {
    /// The referee's result, without `shot`.
    pub referee: Value,
    /// The shot.
    pub shot: ShotView,
    /// The frame after the stroke; `null` when the frame is over.
    pub next: Option<Position>,
}

/// Plays the strike of `frame` (a frame with its `cue`) and judges it.
pub fn stroke(frame: &Value, rate: f64, limits: &Limits) -> Result<StrokeView, ApiError> {
    let file = input::frame(frame, limits)?;
    if file.strike.is_none() {
        return Err(ApiError::bad(
            FRAME,
            "cue",
            "a frame to referee needs its [cue] strike (on the cue ball)",
        ));
    }
    let shot = shot::simulate(&file.scene, FRAME)?;
    let verdict = file
        .frame
        .judge(&shot)
        .map_err(|e| ApiError::unfinished(FRAME, e.to_string()))?;
    let referee = serde_json::to_value(verdict.report::<ShotRecord>(None))
        .map_err(|e| ApiError::internal(e.to_string()))?;
    let next = match file.frame.next(&verdict) {
        Next::Play(f) => Some(position::of_frame(&f)?),
        Next::Over { .. } => None,
    };
    Ok(StrokeView {
        referee,
        shot: shot::view(&file.scene, &shot, rate, limits),
        next,
    })
}
