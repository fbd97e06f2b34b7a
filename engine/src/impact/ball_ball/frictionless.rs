//! Frictionless ball-ball impact with Newton's restitution along the line of centres
//! (thesis §2.4.3: V1 + V2 = V cos(theta), V2 - V1 = e V cos(theta), equal masses).
//! The impulse passes through both centres, so spins are unchanged.

use crate::ball::BallState;
use crate::params::Params;

/// States just after the impact of `a` on `b`.
pub fn resolve(a: &BallState, b: &BallState, p: &Params) -> (BallState, BallState) {
    let n = (b.pos - a.pos).normalize();
    let approach = (a.vel - b.vel).dot(&n);
    let mut a2 = *a;
    let mut b2 = *b;
    if approach > 0.0 {
        // Equal masses: each ball's normal velocity changes by (1 + e)/2 of the approach speed.
        let dv = 0.5 * (1.0 + p.e_ball) * approach * n;
        a2.vel -= dv;
        b2.vel += dv;
    }
    (a2, b2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::{Motion, Vec3};

    #[test]
    fn head_on_newton() {
        let p = Params::default();
        let r = p.ball_radius;
        let a = BallState {
            pos: Vec3::new(0.0, 0.0, r),
            vel: Vec3::new(1.0, 0.0, 0.0),
            spin: Vec3::new(0.0, 1.0 / r, 0.0),
            motion: Motion::Rolling,
        };
        let b = BallState::at_rest(2.0 * r, 0.0, r);
        let (a2, b2) = resolve(&a, &b, &p);
        assert!((a2.vel.x - (1.0 - p.e_ball) / 2.0).abs() < 1e-15);
        assert!((b2.vel.x - (1.0 + p.e_ball) / 2.0).abs() < 1e-15);
        assert_eq!(a2.spin, a.spin);
    }
}
