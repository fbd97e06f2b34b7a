//! Free flight after a ball-ball impact lifts a ball off the cloth (thesis §6.1.6):
//! a ballistic parabola; horizontal velocity and spin are frozen in the air.
//! On landing the cloth's vertical impulse removes the vertical velocity; its friction
//! percussion is neglected, as in the thesis.

use crate::ball::{BallState, Vec3};
use crate::params::Params;

/// Acceleration in flight (gravity, with its small component along a tilted bed).
pub fn acceleration(p: &Params) -> Vec3 {
    super::cloth::slope(p) - Vec3::new(0.0, 0.0, p.g)
}

/// Time until the centre comes back down to height R.
pub fn duration(s: &BallState, p: &Params) -> f64 {
    let h = (s.pos.z - p.ball_radius).max(0.0);
    let vz = s.vel.z;
    (vz + (vz * vz + 2.0 * p.g * h).sqrt()) / p.g
}

/// Height of the flight's peak above the resting height R, m: the present height plus
/// vz^2 / 2g while rising.
pub fn peak_height(s: &BallState, p: &Params) -> f64 {
    let h = (s.pos.z - p.ball_radius).max(0.0);
    h + s.vel.z.max(0.0).powi(2) / (2.0 * p.g)
}

/// State after `dt` seconds of flight.
pub fn state_at(s: &BallState, dt: f64, p: &Params) -> BallState {
    let mut out = *s;
    out.pos = s.pos + s.vel * dt + 0.5 * dt * dt * acceleration(p);
    out.vel = s.vel + dt * acceleration(p);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Motion;

    #[test]
    fn lands_after_two_vz_over_g() {
        let p = Params::default();
        let s = BallState {
            pos: Vec3::new(1.0, 1.0, p.ball_radius),
            vel: Vec3::new(1.0, 0.0, 0.2),
            spin: Vec3::new(1.0, 2.0, 3.0),
            motion: Motion::Airborne,
        };
        let t = duration(&s, &p);
        assert!((t - 0.4 / p.g).abs() < 1e-15);
        let e = state_at(&s, t, &p);
        assert!((e.pos.z - p.ball_radius).abs() < 1e-15);
        assert_eq!(e.spin, s.spin);
    }
}
