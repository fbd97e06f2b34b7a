//! A shot in one row: what a sweep over many shots tabulates (the Parquet table's columns,
//! [`crate::table`]). Every ball's final position and motion, the pots, the duration and the
//! event count; a scene that failed has its error and nothing else.

use crate::Outcome;
use snooker_engine::{Ending, EventKind, Shot};
use snooker_scene::Scene;
use snooker_scene::result::departures;

/// One shot's summary.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    /// Where the scene came from (file, or `FILE:LINE`).
    pub source: String,
    /// The scene's name (empty if it could not be read).
    pub scene: String,
    /// Why the scene could not be read or simulated; `None` for a shot.
    pub error: Option<String>,
    /// How the shot ended: `at_rest` or `horizon`.
    pub ending: Option<&'static str>,
    /// Simulated duration, s.
    pub duration: Option<f64>,
    /// Events resolved.
    pub events: Option<u64>,
    /// The balls potted, in time order, with their pockets and times (s).
    pub pots: Vec<(String, String, f64)>,
    /// Every ball: id, final position (m) and final motion.
    pub balls: Vec<(String, [f64; 3], &'static str)>,
}

impl Summary {
    /// The summary of `shot`, simulated from `scene` (read from `source`).
    pub fn of_shot(source: &str, scene: &Scene, shot: &Shot) -> Summary {
        let ids: Vec<&str> = shot.tracks.iter().map(|t| t.id.as_str()).collect();
        Summary {
            source: source.into(),
            scene: scene.name.clone(),
            error: None,
            ending: Some(match shot.ending {
                Ending::AtRest => "at_rest",
                Ending::Horizon => "horizon",
            }),
            duration: Some(shot.duration),
            events: Some(shot.events.len() as u64),
            pots: departures(shot, EventKind::BallPocket)
                .map(|(b, pocket, t)| (ids[b].to_string(), pocket.to_string(), t))
                .collect(),
            balls: ids
                .iter()
                .zip(shot.final_states())
                .map(|(id, s)| (id.to_string(), [s.pos.x, s.pos.y, s.pos.z], s.motion.name()))
                .collect(),
        }
    }

    /// The row of an outcome from `source`.
    pub fn of_outcome(source: &str, outcome: &Outcome) -> Summary {
        match (&outcome.scene, &outcome.shot) {
            (Ok(scene), Some(Ok(shot))) => Summary::of_shot(source, scene, shot),
            _ => Summary::of_error(
                source,
                outcome.scene.as_ref().ok(),
                outcome.error().unwrap_or_default(),
            ),
        }
    }

    /// The row of a scene that failed: `error` says why.
    pub fn of_error(source: &str, scene: Option<&Scene>, error: String) -> Summary {
        Summary {
            source: source.into(),
            scene: scene.map_or(String::new(), |s| s.name.clone()),
            error: Some(error),
            ending: None,
            duration: None,
            events: None,
            pots: Vec::new(),
            balls: Vec::new(),
        }
    }
}
