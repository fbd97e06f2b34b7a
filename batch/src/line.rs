//! A batch's JSON lines: per scene, the result document of `snooker simulate --json`
//! (`snooker_scene::result`, on one line) with the scene's `source` added, or, for a scene
//! that could not be read or simulated, `{"source", "scene", "error"}`.

use crate::Outcome;
use serde_json::{Value, json};
use snooker_engine::{Shot, SimError};
use snooker_scene::Scene;
use snooker_scene::result::result_json;

/// The line of `scene` (from `source`) simulated to `shot`.
pub fn json_line(source: &str, scene: &Scene, shot: &Result<Shot, SimError>) -> Value {
    match shot {
        Ok(shot) => {
            let mut doc = result_json(scene, shot);
            if let Value::Object(map) = &mut doc {
                map.insert("source".into(), json!(source));
            }
            doc
        }
        Err(e) => json!({"source": source, "scene": scene.name, "error": e.to_string()}),
    }
}

/// The line of an outcome from `source`.
pub fn outcome_line(source: &str, outcome: &Outcome) -> Value {
    match (&outcome.scene, &outcome.shot) {
        (Ok(scene), Some(shot)) => json_line(source, scene, shot),
        _ => json!({
            "source": source,
            "scene": outcome.scene.as_ref().map_or("", |s| s.name.as_str()),
            "error": outcome.error(),
        }),
    }
}
