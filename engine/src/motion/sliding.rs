//! Sliding: the cloth contact point slips with velocity u; kinetic friction mu_s M g acts
//! against u (thesis §2.4.2, §6.1.5). Then
//!   dv/dt = -mu_s g u^,   dw_xy/dt = (5 mu_s g / 2R) (e_z x u^),
//! so u keeps its direction and shrinks at (7/2) mu_s g: sliding lasts 2|u0| / (7 mu_s g) and
//! the centre follows a parabola (the massé curve, thesis §6.1.5). Sidespin decays on its own
//! ([`super::spinning`]).

use super::spinning::sidespin_at;
use crate::ball::{BallState, Vec3};
use crate::params::Params;

/// Unit vector along the slip, or zero when there is none.
pub fn slip_direction(s: &BallState, p: &Params) -> Vec3 {
    let u = s.slip(p.ball_radius);
    let n = u.norm();
    if n > 0.0 { u / n } else { Vec3::zeros() }
}

/// Acceleration of the centre while sliding, m/s^2.
pub fn acceleration(s: &BallState, p: &Params) -> Vec3 {
    -p.mu_slide * p.g * slip_direction(s, p)
}

/// How long sliding lasts: 2|u0| / (7 mu_s g) (infinite on frictionless cloth).
pub fn duration(s: &BallState, p: &Params) -> f64 {
    let u = s.slip(p.ball_radius).norm();
    if p.mu_slide > 0.0 {
        2.0 * u / (7.0 * p.mu_slide * p.g)
    } else {
        f64::INFINITY
    }
}

/// State after `dt` seconds of sliding (valid for 0 <= dt <= [`duration`]).
pub fn state_at(s: &BallState, dt: f64, p: &Params) -> BallState {
    let uhat = slip_direction(s, p);
    let f = p.mu_slide * p.g;
    let mut out = *s;
    out.pos = s.pos + s.vel * dt - 0.5 * f * dt * dt * uhat;
    out.vel = s.vel - f * dt * uhat;
    let dw = (2.5 * f / p.ball_radius * dt) * Vec3::z().cross(&uhat);
    out.spin.x = s.spin.x + dw.x;
    out.spin.y = s.spin.y + dw.y;
    out.spin.z = sidespin_at(s.spin.z, dt, p.sidespin_decel);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Motion;

    fn ball(vel: Vec3, spin: Vec3) -> BallState {
        BallState {
            pos: Vec3::new(0.5, 0.5, 0.0262),
            vel,
            spin,
            motion: Motion::Sliding,
        }
    }

    #[test]
    fn stun_rolls_at_five_sevenths() {
        let p = Params::default();
        let v0 = 2.0;
        let s = ball(Vec3::new(v0, 0.0, 0.0), Vec3::zeros());
        let t = duration(&s, &p);
        assert!((t - 2.0 * v0 / (7.0 * p.mu_slide * p.g)).abs() < 1e-15);
        let e = state_at(&s, t, &p);
        assert!((e.vel.x - 5.0 / 7.0 * v0).abs() < 1e-12);
        assert!(e.slip(p.ball_radius).norm() < 1e-12);
    }

    #[test]
    fn derivatives_match_the_law() {
        // Finite differences of position and velocity against the stated accelerations.
        let p = Params::default();
        let s = ball(Vec3::new(1.0, -0.4, 0.0), Vec3::new(20.0, -5.0, 3.0));
        let h = 1e-6;
        let t = 0.3 * duration(&s, &p);
        let a = state_at(&s, t - h, &p);
        let b = state_at(&s, t + h, &p);
        let m = state_at(&s, t, &p);
        assert!(((b.pos - a.pos) / (2.0 * h) - m.vel).norm() < 1e-8);
        assert!(((b.vel - a.vel) / (2.0 * h) - acceleration(&s, &p)).norm() < 1e-6);
        let dw = (b.spin - a.spin) / (2.0 * h);
        let expect =
            2.5 * p.mu_slide * p.g / p.ball_radius * Vec3::z().cross(&slip_direction(&s, &p));
        assert!((dw.xy() - expect.xy()).norm() < 1e-4);
        // Slip keeps its direction and shrinks at 7/2 mu_s g.
        let du = (b.slip(p.ball_radius) - a.slip(p.ball_radius)) / (2.0 * h);
        let expect = -3.5 * p.mu_slide * p.g * slip_direction(&s, &p);
        assert!((du - expect).norm() < 1e-6);
    }
}
