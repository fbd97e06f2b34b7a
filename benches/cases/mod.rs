//! The impacts that `benches/impacts.rs` times and `engine/examples/impact_count.rs` counts.

use snooker_engine::{BallState, Motion, Params, Vec3};

/// A rolling cue ball with sidespin meeting a red at a 30-degree cut, 2 m/s: (cue, red).
pub fn ball_ball(p: &Params) -> (BallState, BallState) {
    let r = p.ball_radius;
    let cut = 30f64.to_radians();
    let cue = BallState {
        pos: Vec3::new(0.0, 0.0, r),
        vel: Vec3::new(2.0, 0.0, 0.0),
        spin: Vec3::new(0.0, 2.0 / r, 1.0 / r),
        motion: Motion::Rolling,
    };
    (
        cue,
        BallState::at_rest(2.0 * r * cut.cos(), 2.0 * r * cut.sin(), r),
    )
}

/// A rolling ball into a cushion (normal +y) at 45 degrees, 1 m/s.
pub fn cushion(p: &Params) -> BallState {
    let a = 45f64.to_radians();
    let v = Vec3::new(a.cos(), -a.sin(), 0.0);
    BallState {
        pos: Vec3::new(1.0, p.cushion_contact_distance(), p.ball_radius),
        vel: v,
        spin: Vec3::z().cross(&v) / p.ball_radius,
        motion: Motion::Rolling,
    }
}
