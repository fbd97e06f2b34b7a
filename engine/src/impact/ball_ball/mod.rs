//! Ball-ball impact models.

pub mod frictionless;
pub mod mathavan;

use crate::ball::BallState;
use crate::impact::impulse::ImpactError;
use crate::params::Params;
use serde::{Deserialize, Serialize};

/// Which law resolves a ball-ball impact.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BallBallModel {
    /// Newton's restitution e along the line of centres; no friction, spins untouched.
    Frictionless,
    /// The thesis's frictional 3D impact (§6.1): ball-ball and ball-cloth friction, one ball
    /// lifting off, energetic restitution.
    #[default]
    Mathavan,
}

impl BallBallModel {
    /// The model's name in scene files.
    pub fn name(self) -> &'static str {
        match self {
            BallBallModel::Frictionless => "frictionless",
            BallBallModel::Mathavan => "mathavan",
        }
    }

    /// Resolves the impact of `a` on `b` (touching, approaching): the states just after.
    pub fn resolve(
        self,
        a: &BallState,
        b: &BallState,
        p: &Params,
    ) -> Result<(BallState, BallState), ImpactError> {
        match self {
            BallBallModel::Frictionless => Ok(frictionless::resolve(a, b, p)),
            BallBallModel::Mathavan => mathavan::resolve(a, b, p),
        }
    }
}
