//! What happens at an impact. Each model is a pure function from the pre-impact states (and
//! the parameters) to the post-impact states; which model runs is a value chosen per scene.

pub mod ball_ball;
pub mod cushion;
pub(crate) mod dopri;
pub mod impulse;
pub mod incoming;
pub mod separation;
#[cfg(feature = "sweep")]
pub mod sweep;

use serde::{Deserialize, Serialize};

pub use ball_ball::BallBallModel;
pub use separation::{GRAZING_APPROACH, MIN_SEPARATION};

pub use cushion::{CushionContact, CushionModel};
pub use impulse::ImpactError;

/// The impact models of a scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Models {
    /// Ball-ball impacts.
    pub ball_ball: BallBallModel,
    /// Ball-cushion (and jaw) impacts.
    pub cushion: CushionModel,
}
