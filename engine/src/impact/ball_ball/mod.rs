//! Ball-ball impact models.

pub mod frictionless;

use crate::ball::BallState;
use crate::params::Params;
use serde::{Deserialize, Serialize};

/// Which law resolves a ball-ball impact.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BallBallModel {
    /// Newton's restitution e along the line of centres; no friction, spins untouched.
    #[default]
    Frictionless,
}

impl BallBallModel {
    /// The model's name in scene files.
    pub fn name(self) -> &'static str {
        match self {
            BallBallModel::Frictionless => "frictionless",
        }
    }

    /// Resolves the impact of `a` on `b` (touching, approaching): the states just after.
    pub fn resolve(self, a: &BallState, b: &BallState, p: &Params) -> (BallState, BallState) {
        match self {
            BallBallModel::Frictionless => frictionless::resolve(a, b, p),
        }
    }
}
