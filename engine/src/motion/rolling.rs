//! Rolling: no slip at the cloth (v = w x R e_z); rolling resistance decelerates the ball at
//! mu_r g along a straight line (thesis §2.4.2, eq. V = V0 - mu_r g t; mu_r from §5.1.1.1).
//! Sidespin decays on its own ([`super::spinning`]).

use super::spinning::sidespin_at;
use crate::ball::{BallState, Vec3};
use crate::params::Params;

fn direction(s: &BallState) -> Vec3 {
    let v = Vec3::new(s.vel.x, s.vel.y, 0.0);
    let n = v.norm();
    if n > 0.0 { v / n } else { Vec3::zeros() }
}

/// Acceleration of the centre while rolling, m/s^2.
pub fn acceleration(s: &BallState, p: &Params) -> Vec3 {
    -p.mu_roll * p.g * direction(s)
}

/// How long rolling lasts: |v0| / (mu_r g) (infinite without rolling resistance).
pub fn duration(s: &BallState, p: &Params) -> f64 {
    if p.mu_roll > 0.0 {
        s.vel.xy().norm() / (p.mu_roll * p.g)
    } else {
        f64::INFINITY
    }
}

/// State after `dt` seconds of rolling (valid for 0 <= dt <= [`duration`]).
pub fn state_at(s: &BallState, dt: f64, p: &Params) -> BallState {
    let d = direction(s);
    let f = p.mu_roll * p.g;
    let mut out = *s;
    out.pos = s.pos + s.vel * dt - 0.5 * f * dt * dt * d;
    out.vel = s.vel - f * dt * d;
    let w = Vec3::z().cross(&out.vel) / p.ball_radius;
    out.spin = Vec3::new(w.x, w.y, sidespin_at(s.spin.z, dt, p.sidespin_decel));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Motion;

    #[test]
    fn stops_after_v_squared_over_two_mu_g() {
        let p = Params::default();
        let v = Vec3::new(0.6, 0.8, 0.0);
        let s = BallState {
            pos: Vec3::new(1.0, 1.0, p.ball_radius),
            vel: v,
            spin: Vec3::new(0.0, 0.0, 5.0) + Vec3::z().cross(&v) / p.ball_radius,
            motion: Motion::Rolling,
        };
        let t = duration(&s, &p);
        let e = state_at(&s, t, &p);
        let dist = (e.pos - s.pos).norm();
        assert!((dist - 1.0 / (2.0 * p.mu_roll * p.g)).abs() < 1e-12);
        assert!(e.vel.norm() < 1e-15);
        assert!(e.slip(p.ball_radius).norm() < 1e-15);
        // Sidespin decayed on its own clock.
        assert!((e.spin.z - (5.0 - p.sidespin_decel * t).max(0.0)).abs() < 1e-12);
    }
}
