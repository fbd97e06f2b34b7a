//! A batch's JSON lines: per scene, the result document of `snooker simulate --json`
//! (`snooker_scene::result`, on one line) with the scene's `source` added, or, for a scene
//! that could not be read or simulated, `{"source", "scene", "error"}`.

use crate::Outcome;
use serde::Serialize;
use snooker_engine::{Shot, SimError};
use snooker_scene::Scene;
use snooker_scene::result::{ShotRecord, result_record};

/// One line of a batch's output.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Line {
    /// A shot: the result document with its source after it.
    Shot {
        /// The result document.
        #[serde(flatten)]
        record: Box<ShotRecord>,
        /// The file, or `FILE:LINE`.
        source: String,
    },
    /// A scene that could not be read or simulated.
    Failed {
        /// The file, or `FILE:LINE`.
        source: String,
        /// The scene's name (empty when it could not be read).
        scene: String,
        /// Why (null only for an outcome that was neither read nor simulated).
        error: Option<String>,
    },
}

/// The line of `scene` (from `source`) simulated to `shot`.
pub fn json_line(source: &str, scene: &Scene, shot: &Result<Shot, SimError>) -> Line {
    match shot {
        Ok(shot) => Line::Shot {
            record: Box::new(result_record(scene, shot)),
            source: source.into(),
        },
        Err(e) => Line::Failed {
            source: source.into(),
            scene: scene.name.clone(),
            error: Some(e.to_string()),
        },
    }
}

/// The line of an outcome from `source`.
pub fn outcome_line(source: &str, outcome: &Outcome) -> Line {
    match (&outcome.scene, &outcome.shot) {
        (Ok(scene), Some(shot)) => json_line(source, scene, shot),
        _ => Line::Failed {
            source: source.into(),
            scene: outcome
                .scene
                .as_ref()
                .map_or(String::new(), |s| s.name.clone()),
            error: outcome.error(),
        },
    }
}
