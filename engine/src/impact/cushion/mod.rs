//! Ball-cushion impact models (the same models serve the jaws, about the local normal).

pub mod frictionless;
pub mod mathavan;

use crate::ball::{BallState, Vec3};
use crate::impact::impulse::ImpactError;
use crate::params::Params;
use serde::{Deserialize, Serialize};

/// Which law resolves a ball-cushion impact.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CushionModel {
    /// Restitution e_e on the normal velocity, tangential velocity and spin kept.
    Frictionless,
    /// The thesis's frictional 3D impact (§6.2): nose at height h, cushion and cloth friction,
    /// energetic restitution.
    #[default]
    Mathavan,
}

impl CushionModel {
    /// The model's name in scene files.
    pub fn name(self) -> &'static str {
        match self {
            CushionModel::Frictionless => "frictionless",
            CushionModel::Mathavan => "mathavan",
        }
    }

    /// Resolves the impact of `ball` on a cushion whose plan normal (from the cushion towards
    /// the ball) is `normal`: the state just after.
    pub fn resolve(
        self,
        ball: &BallState,
        normal: Vec3,
        p: &Params,
    ) -> Result<BallState, ImpactError> {
        match self {
            CushionModel::Frictionless => Ok(frictionless::resolve(ball, normal, p)),
            CushionModel::Mathavan => mathavan::resolve(ball, normal, p),
        }
    }
}
