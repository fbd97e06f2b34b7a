//! The record of a simulated shot: its events and every ball's piecewise trajectory, which
//! can be evaluated exactly at any time.

use super::event::{Event, EventKind};
use crate::ball::{Ball, BallKind, BallState};
use crate::motion;
use crate::params::Params;
use serde::{Deserialize, Serialize};

/// A stretch of one ball's trajectory: from `t` on, the law of `state.motion` starting at `state`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Segment {
    /// Start time, s.
    pub t: f64,
    /// State at `t`.
    pub state: BallState,
}

/// One ball's history.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Track {
    /// Ball name.
    pub id: String,
    /// Ball colour.
    pub kind: BallKind,
    /// Segments in time order (several may start at the same instant).
    pub segments: Vec<Segment>,
}

impl Track {
    /// The ball's state at time `t` (the latest segment starting at or before `t`).
    pub fn state_at(&self, t: f64, p: &Params) -> BallState {
        let i = self.segments.partition_point(|s| s.t <= t).max(1) - 1;
        let seg = &self.segments[i];
        motion::state_at(&seg.state, t - seg.t, p)
    }
}

/// Why a shot ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Ending {
    /// Every ball is at rest or pocketed.
    AtRest,
    /// The requested horizon was reached with balls still moving.
    Horizon,
}

/// Counters describing the work done.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Stats {
    /// Events resolved (the cap `max_events` counts these).
    pub events: usize,
    /// `lift_off` events listed after the impacts that lifted a ball: in the shot's events,
    /// not resolved on their own, so not counted in `events`.
    pub lift_offs: usize,
    /// Candidates popped that were stale.
    pub stale: usize,
    /// Candidates computed.
    pub candidates: usize,
    /// Law segments renewed with the cloth's extra effects on: not events (neither listed nor
    /// counted in `events`).
    pub refreshes: usize,
}

/// A simulated shot.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Shot {
    /// Parameters used.
    pub params: Params,
    /// Events in time order.
    pub events: Vec<Event>,
    /// One track per ball, in the scene's order.
    pub tracks: Vec<Track>,
    /// Time of the end of the shot, s.
    pub duration: f64,
    /// Why it ended.
    pub ending: Ending,
    /// Work counters.
    pub stats: Stats,
}

impl Shot {
    /// The events resolved: all but the `lift_off`s, which stand at their impact's instant
    /// (what bounds a recording's instants; `stats.events` for a shot simulated whole).
    pub fn resolved_events(&self) -> usize {
        self.events
            .iter()
            .filter(|e| e.kind != EventKind::LiftOff)
            .count()
    }

    /// Every ball's state at the end of the shot.
    pub fn final_states(&self) -> Vec<BallState> {
        self.tracks
            .iter()
            .map(|tr| tr.state_at(self.duration, &self.params))
            .collect()
    }

    /// The balls at time `t`, as [`Ball`]s (ids, kinds and states).
    pub fn balls_at(&self, t: f64) -> Vec<Ball> {
        self.tracks
            .iter()
            .map(|tr| Ball {
                id: tr.id.clone(),
                kind: tr.kind,
                state: tr.state_at(t, &self.params),
            })
            .collect()
    }

    /// Index of the ball with this id.
    pub fn index_of(&self, id: &str) -> Option<usize> {
        self.tracks.iter().position(|t| t.id == id)
    }
}
