//! The thesis's impact set-ups in the table frame, with spins in the thesis's units of V/R
//! (1 = rolling): the cue ball moving along +x into a resting object ball at a cut angle
//! (thesis §6.1.4.1, figs. 6.14, 6.15), and a ball meeting a cushion at an angle of incidence
//! (thesis §6.2.4, Mathavan et al. 2010). Used by `snooker impact`, the convergence sweeps
//! (`impact::sweep`, behind the `sweep` feature) and the impact benches.

use crate::ball::{BallState, Motion, Vec3};
use crate::params::Params;

/// The ball-ball set-up: the cue ball moves along +x at `v` (m/s) with topspin `topspin` V/R
/// about the axis of rolling and sidespin `sidespin` V/R about +z (anticlockwise from above);
/// the object ball rests touching it at cut angle `cut` (rad; the line of centres at `cut`
/// from +x, the object ball to the left for a positive cut). Returns (cue, object).
pub fn ball_ball(
    v: f64,
    cut: f64,
    topspin: f64,
    sidespin: f64,
    p: &Params,
) -> (BallState, BallState) {
    let r = p.ball_radius;
    let cue = BallState {
        pos: Vec3::new(0.0, 0.0, r),
        vel: Vec3::new(v, 0.0, 0.0),
        spin: Vec3::new(0.0, topspin * v / r, sidespin * v / r),
        motion: Motion::Sliding,
    };
    let object = BallState::at_rest(2.0 * r * cut.cos(), 2.0 * r * cut.sin(), r);
    (cue, object)
}

/// The cushion set-up: a ball touching the cushion along y = 0 (plan normal +y, the ball on
/// the +y side) meets it at `v` (m/s) and `incidence` (rad from the cushion line, moving
/// towards +x), with topspin `topspin` V/R (1 = rolling) and sidespin `sidespin` V/R.
pub fn cushion(v: f64, incidence: f64, topspin: f64, sidespin: f64, p: &Params) -> BallState {
    let r = p.ball_radius;
    let vel = v * Vec3::new(incidence.cos(), -incidence.sin(), 0.0);
    let roll = Vec3::z().cross(&vel) / r;
    BallState {
        pos: Vec3::new(1.0, p.cushion_contact_distance(), r),
        vel,
        spin: topspin * roll + Vec3::new(0.0, 0.0, sidespin * v / r),
        motion: Motion::Sliding,
    }
}

/// The typical ball-ball impact the impact benches time and `examples/impact_count.rs`
/// counts: a rolling cue ball with sidespin (0.5 V/R) meeting a red at a 30-degree cut,
/// 2 m/s. Returns (cue, red).
pub fn typical_ball_ball(p: &Params) -> (BallState, BallState) {
    ball_ball(2.0, 30f64.to_radians(), 1.0, 0.5, p)
}

/// The typical cushion impact of the benches: a rolling ball into a cushion (plan normal +y)
/// at 45 degrees, 1 m/s.
pub fn typical_cushion(p: &Params) -> BallState {
    cushion(1.0, 45f64.to_radians(), 1.0, 0.0, p)
}
