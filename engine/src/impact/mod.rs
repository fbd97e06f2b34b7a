//! What happens at an impact. Each model is a pure function from the pre-impact states (and
//! the parameters) to the post-impact states; which model runs is a value chosen per scene.

pub mod ball_ball;
pub mod cushion;
pub mod dopri;
pub mod impulse;
pub mod incoming;
pub mod sweep;

use serde::{Deserialize, Serialize};

pub use ball_ball::BallBallModel;

/// Smallest separation speed after an impact, m/s.
///
/// A ball pressed against another ball (or a cushion) by its own acceleration meets it again
/// and again, each bounce slower (restitution below 1 and the cloth's friction after each
/// impact), infinitely often in a finite time: the series converges to a sustained contact,
/// which no polynomial law describes. Following the impulse-based treatment of resting contact
/// (Mirtich and Canny 1995), every impact separates the bodies at no less than this speed, so a
/// sustained contact becomes a steady train of micro-collisions whose impulses average to the
/// contact force, the bodies never more than a few micrometres apart. The price is bounded: an
/// impact slower than this gains at most 1/2 m_eff (1 mm/s)^2 (3.5e-8 J for two balls), which
/// the cloth's friction then removes.
pub const MIN_SEPARATION: f64 = 1e-3;

/// The restitution coefficient to use for an impact at `approach` m/s when the model's is `e`:
/// `e`, raised where needed so that the separation speed is at least [`MIN_SEPARATION`].
pub fn restitution_floor(e: f64, approach: f64) -> f64 {
    if approach > 0.0 {
        e.max(MIN_SEPARATION / approach)
    } else {
        e
    }
}
pub use cushion::CushionModel;
pub use impulse::ImpactError;

/// The impact models of a scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Models {
    /// Ball-ball impacts.
    pub ball_ball: BallBallModel,
    /// Ball-cushion (and jaw) impacts.
    pub cushion: CushionModel,
}
