//! A shot simulated for the page: the engine on a checked scene, with the server's limits; the
//! result document (`snooker simulate`'s JSON) and the balls' paths; and the shot's downloads:
//! the scene as TOML, the JSON result and the Rerun recording, the same bytes the command line
//! writes.

use crate::error::ApiError;
use crate::input::CheckedScene;
use crate::limits::Limits;
use crate::paths::{self, Paths};
use serde::Serialize;
use snooker_engine::Shot;
use snooker_engine::shown::Shown;
use snooker_scene::Scene;
use snooker_scene::result::{ShotRecord, result_record};

/// A shot as the page shows it.
#[derive(Debug, Clone, Serialize)]
pub struct ShotView {
    /// The result document, as `snooker simulate` writes it.
    pub result: ShotRecord,
    /// The balls' paths.
    pub paths: Paths,
}

/// Simulates `scene`; a valid scene that does not finish within the server's limits is 422.
pub fn simulate(scene: &Scene, file: &str) -> Result<Shot, ApiError> {
    snooker_engine::simulate(&scene.setup, &scene.options)
        .map_err(|e| ApiError::unfinished(file, e.to_string()))
}

/// The view of `shot` of `scene`, paths at `rate` Hz (at most the limit's).
pub fn view(scene: &Scene, shot: &Shot, rate: f64, limits: &Limits) -> ShotView {
    ShotView {
        result: result_record(scene, shot),
        paths: paths::sample(shot, rate.min(limits.path_rate), limits.path_points),
    }
}

/// The checked rate of a request, Hz.
pub fn rate(rate: Option<f64>, limits: &Limits) -> Result<f64, ApiError> {
    match rate {
        None => Ok(limits.path_rate.min(120.0)),
        Some(r) if r.is_finite() && r > 0.0 && r <= limits.path_rate => Ok(r),
        Some(r) => Err(ApiError::bad(
            crate::body::REQUEST,
            "rate",
            format!(
                "the sample rate must lie in (0, {}] Hz, got {}",
                limits.path_rate,
                Shown(r)
            ),
        )),
    }
}

/// The JSON result of `scene` as `snooker simulate` writes it to a file: the same bytes.
pub fn result_json(checked: &CheckedScene, file: &str) -> Result<String, ApiError> {
    let shot = simulate(&checked.scene, file)?;
    let doc = result_record(&checked.scene, &shot);
    let text = serde_json::to_string_pretty(&doc)
        .map_err(|e| ApiError::internal(format!("the result as JSON: {e}")))?;
    Ok(text + "\n")
}
