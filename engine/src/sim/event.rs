//! Events as they appear in a shot's record.

use crate::ball::BallState;
use crate::motion::Transition;
use serde::{Deserialize, Serialize};

/// What happened.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EventKind {
    /// Two balls collided.
    BallBall,
    /// A ball hit a cushion nose, a jaw or a pocket facing.
    BallCushion,
    /// A ball dropped into a pocket.
    BallPocket,
    /// A ball flew over a cushion and left the table.
    BallOffTable,
    /// A ball left the cloth: an impact on the cloth sent it into the air. The impact's event
    /// comes first, at the same instant; this one's `before` and `after` are both the ball's
    /// state as it leaves (formats.md's `lift_off`).
    LiftOff,
    /// A ball's motion law changed on its own.
    Transition(Transition),
}

impl EventKind {
    /// The kind's name in the JSON result (formats.md).
    pub fn name(self) -> &'static str {
        match self {
            EventKind::BallBall => "ball_ball",
            EventKind::BallCushion => "ball_cushion",
            EventKind::BallPocket => "ball_pocket",
            EventKind::BallOffTable => "ball_off_table",
            EventKind::LiftOff => "lift_off",
            EventKind::Transition(t) => t.name(),
        }
    }

    /// The kind of that JSON name, the inverse of [`EventKind::name`].
    pub fn from_name(name: &str) -> Option<EventKind> {
        [
            EventKind::BallBall,
            EventKind::BallCushion,
            EventKind::BallPocket,
            EventKind::BallOffTable,
            EventKind::LiftOff,
        ]
        .into_iter()
        .chain(Transition::ALL.map(EventKind::Transition))
        .find(|k| k.name() == name)
    }
}

/// One event of a shot.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Event {
    /// Time since the start of the shot, s.
    pub t: f64,
    /// What happened.
    pub kind: EventKind,
    /// Indices of the balls involved (into the shot's ball list).
    pub balls: Vec<usize>,
    /// Their states just after the event, in the same order.
    pub after: Vec<BallState>,
    /// Their states just before the event, in the same order.
    pub before: Vec<BallState>,
    /// The cushion, jaw or pocket involved, by name.
    pub feature: Option<String>,
    /// For impacts: the approach speed along the contact normal (plan normal for cushions), m/s.
    pub normal_speed: Option<f64>,
}
