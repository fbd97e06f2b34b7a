//! When things happen: the first time, within a window in which both laws hold, that a ball
//! touches another ball, a cushion nose, a jaw, or enters a pocket's fall.
//!
//! Every test is a polynomial in the time since "now" (ball paths are quadratics in time),
//! searched only inside the window where the current laws are valid, with roots accepted
//! only where the bodies approach and the distance is verified there.

pub mod ball_ball;
pub mod bounds;
pub mod cushion;
pub mod pocket;
pub mod roots;

/// Distance within which two bodies count as touching now, m.
pub const TOUCH_TOL: f64 = 1e-9;
/// Contact skin, m: crossings are searched at the contact distance minus this. A cushion's
/// line is then crossed, and found, by a ball placed exactly touching it and pushed from zero
/// relative velocity, instead of sinking in unseen; a pair of balls touching within
/// [`TOUCH_TOL`] and pressed together is a contact at once (`roots::entries`). Far below any
/// measurable length.
pub const SKIN: f64 = 1e-10;
/// A root is accepted only if the contact distance there is right to within this, m.
pub const VERIFY_TOL: f64 = 1e-9;
/// Accuracy asked of the root finder, s.
pub const ROOT_TIME_TOL: f64 = 1e-14;
