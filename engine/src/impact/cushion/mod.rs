//! Ball-cushion impact models (the same models serve the jaws, about the local normal).

pub mod frictionless;

use crate::ball::{BallState, Vec3};
use crate::params::Params;
use serde::{Deserialize, Serialize};

/// Which law resolves a ball-cushion impact.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CushionModel {
    /// Restitution e_e on the normal velocity, tangential velocity and spin kept.
    #[default]
    Frictionless,
}

impl CushionModel {
    /// The model's name in scene files.
    pub fn name(self) -> &'static str {
        match self {
            CushionModel::Frictionless => "frictionless",
        }
    }

    /// Resolves the impact of `ball` on a cushion whose plan normal (from the cushion towards
    /// the ball) is `normal`: the state just after.
    pub fn resolve(self, ball: &BallState, normal: Vec3, p: &Params) -> BallState {
        match self {
            CushionModel::Frictionless => frictionless::resolve(ball, normal, p),
        }
    }
}
