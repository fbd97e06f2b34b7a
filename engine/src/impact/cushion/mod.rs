//! Ball-cushion impact models (the same models serve the jaws, about the local normal).

pub mod compliant;
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
    /// The thesis's frictional impact against a cushion that gives way: a rubber of finite
    /// travel on a damped backing, which gives back less of a hard impact's energy (thesis
    /// §6.2.5; Hunt and Crossley 1975; Stronge 2000). The rigid model below the rubber's travel.
    Compliant,
}

impl CushionModel {
    /// The model's name in scene files.
    pub fn name(self) -> &'static str {
        match self {
            CushionModel::Frictionless => "frictionless",
            CushionModel::Mathavan => "mathavan",
            CushionModel::Compliant => "compliant",
        }
    }

    /// Resolves the impact of `ball` on a cushion at `contact`: the state just after.
    pub fn resolve(
        self,
        ball: &BallState,
        contact: CushionContact,
        p: &Params,
    ) -> Result<BallState, ImpactError> {
        match (self, contact) {
            (CushionModel::Frictionless, CushionContact::OnCloth { normal }) => {
                Ok(frictionless::resolve(ball, normal, p))
            }
            (CushionModel::Frictionless, CushionContact::InAir { towards }) => {
                Ok(frictionless::resolve_in_air(ball, towards, p))
            }
            (CushionModel::Mathavan, CushionContact::OnCloth { normal }) => {
                mathavan::resolve(ball, normal, p)
            }
            (CushionModel::Mathavan, CushionContact::InAir { towards }) => {
                mathavan::resolve_in_air(ball, towards, p)
            }
            (CushionModel::Compliant, CushionContact::OnCloth { normal }) => {
                compliant::resolve(ball, normal, p)
            }
            (CushionModel::Compliant, CushionContact::InAir { towards }) => {
                compliant::resolve_in_air(ball, towards, p)
            }
        }
    }
}

/// Where a ball meets a cushion's nose (a straight nose, a jaw or a facing).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CushionContact {
    /// A ball on the cloth: the nose touches it at height h (thesis §6.2). `normal` is the
    /// plan normal, from the cushion towards the ball.
    OnCloth {
        /// Plan normal (unit, horizontal).
        normal: Vec3,
    },
    /// A ball in the air touching the nose edge anywhere on its surface. `towards` is the unit
    /// vector from the ball's centre to the contact point.
    InAir {
        /// From the centre to the contact (unit).
        towards: Vec3,
    },
}

impl CushionContact {
    /// The approach speed of `ball` along the contact's normal, m/s: the plan normal for a
    /// ball on the cloth (the cloth takes the vertical part), the contact normal in the air.
    pub fn approach(&self, ball: &BallState) -> f64 {
        match self {
            CushionContact::OnCloth { normal } => -ball.vel.dot(normal),
            CushionContact::InAir { towards } => ball.vel.dot(towards),
        }
    }
}
