//! Frictionless cushion: the nose pushes along its contact normal (tilted by theta, thesis
//! §6.2), the cloth takes the downward part, so in plan the normal velocity is reversed and
//! scaled by e_e while the tangential velocity and the spin are unchanged.

use crate::ball::{BallState, Vec3};
use crate::params::Params;

/// State just after the impact; `normal` is the plan normal pointing from the cushion to the ball.
pub fn resolve(ball: &BallState, normal: Vec3, p: &Params) -> BallState {
    let vn = ball.vel.dot(&normal);
    let mut out = *ball;
    if vn < 0.0 {
        out.vel -= (1.0 + p.e_cushion) * vn * normal;
    }
    out
}

/// State just after the impact of `ball`, in the air, on a nose edge at `towards` (unit, from
/// its centre to the contact): restitution e_e on the velocity along the contact normal, the
/// rest kept.
pub fn resolve_in_air(ball: &BallState, towards: Vec3, p: &Params) -> BallState {
    let vn = ball.vel.dot(&towards);
    let mut out = *ball;
    if vn > 0.0 {
        out.vel -= (1.0 + p.e_cushion) * vn * towards;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Motion;

    #[test]
    fn keeps_tangential_velocity() {
        let p = Params::default();
        let s = BallState {
            pos: Vec3::new(1.0, 0.024, p.ball_radius),
            vel: Vec3::new(0.7, -1.0, 0.0),
            spin: Vec3::new(3.0, 2.0, 1.0),
            motion: Motion::Sliding,
        };
        let out = resolve(&s, Vec3::y(), &p);
        assert_eq!(out.vel.x, 0.7);
        assert!((out.vel.y - p.e_cushion).abs() < 1e-15);
        assert_eq!(out.spin, s.spin);
    }
}
