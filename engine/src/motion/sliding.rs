//! Sliding: the cloth contact point slips with velocity u; kinetic friction mu_s M g acts
//! against u (thesis §2.4.2, §6.1.5). Then
//!   dv/dt = -mu_s g u^,   dw_xy/dt = (5 mu_s g / 2R) (e_z x u^),
//! so u keeps its direction and shrinks at (7/2) mu_s g: sliding lasts 2|u0| / (7 mu_s g) and
//! the centre follows a parabola (the massé curve, thesis §6.1.5). Sidespin decays on its own
//! ([`super::spinning`]). With the effects of [`super::cloth`] on, the slip no longer keeps
//! its direction; the law then holds its accelerations over short segments.

use super::cloth;
use super::spinning::sidespin_at;
use crate::ball::{BallState, INV_INERTIA_FACTOR, SLIP_RATE_FACTOR, Vec3};
use crate::params::Params;

/// Unit vector along the slip, or zero when there is none.
pub fn slip_direction(s: &BallState, p: &Params) -> Vec3 {
    let u = s.slip(p.ball_radius);
    let n = u.norm();
    if n > 0.0 { u / n } else { Vec3::zeros() }
}

/// The law's constants from its starting state: slip direction, friction coefficient, the
/// extra acceleration of the bed and nap, and the time at which the slip along `uhat` is used
/// up. With the effects of [`cloth`] on they are taken at the middle of the coming segment
/// (the midpoint rule, second order in the segment's length).
struct Law {
    uhat: Vec3,
    mu: f64,
    extra: Vec3,
    natural_end: f64,
}

fn law(s: &BallState, p: &Params) -> Law {
    let u0 = s.slip(p.ball_radius);
    let v0 = Vec3::new(s.vel.x, s.vel.y, 0.0);
    let at = |u: Vec3, v: Vec3| {
        let uhat = u.try_normalize(0.0).unwrap_or(Vec3::zeros());
        let vhat = v.try_normalize(0.0).unwrap_or(Vec3::zeros());
        let mu = cloth::mu_slide(p, u.norm());
        let extra = cloth::body_acceleration(p, vhat);
        // The slip along u^ shrinks at 7/2 mu g less the extra acceleration's share.
        let rate = SLIP_RATE_FACTOR * mu * p.g - extra.dot(&uhat);
        let natural_end = if rate > 0.0 {
            u0.dot(&uhat) / rate
        } else {
            f64::INFINITY
        };
        Law {
            uhat,
            mu,
            extra,
            natural_end,
        }
    };
    let start = at(u0, v0);
    if !cloth::active(p) {
        return start;
    }
    let half = 0.5 * start.natural_end.min(cloth::SEGMENT);
    let dv = half * (start.extra - start.mu * p.g * start.uhat);
    let du = dv - half * INV_INERTIA_FACTOR * start.mu * p.g * start.uhat;
    let mid = at(u0 + du, v0 + dv);
    // Keep the start's direction if the slip would vanish before mid-segment.
    if mid.uhat == Vec3::zeros() {
        start
    } else {
        mid
    }
}

/// Acceleration of the centre while sliding, m/s^2.
pub fn acceleration(s: &BallState, p: &Params) -> Vec3 {
    let l = law(s, p);
    -l.mu * p.g * l.uhat + l.extra
}

/// [`duration`] and [`acceleration`] together, the law taken once (each law's start needs both).
pub fn duration_and_acceleration(s: &BallState, p: &Params) -> (f64, Vec3) {
    let l = law(s, p);
    (held(&l, p), -l.mu * p.g * l.uhat + l.extra)
}

/// How long this law holds: until the slip is used up, 2|u0| / (7 mu_s g) (infinite on
/// frictionless cloth), or for at most one segment with the effects of [`cloth`] on.
pub fn duration(s: &BallState, p: &Params) -> f64 {
    held(&law(s, p), p)
}

/// How long law `l` holds ([`duration`]).
fn held(l: &Law, p: &Params) -> f64 {
    if cloth::active(p) {
        l.natural_end.min(cloth::SEGMENT)
    } else {
        l.natural_end
    }
}

/// True when the law ends because the slip is used up (not at a segment's end).
pub fn ends_rolling(s: &BallState, p: &Params) -> bool {
    let l = law(s, p);
    !cloth::active(p) || l.natural_end <= cloth::SEGMENT
}

/// State after `dt` seconds of sliding (valid for 0 <= dt <= [`duration`]).
pub fn state_at(s: &BallState, dt: f64, p: &Params) -> BallState {
    evolve(s, &law(s, p), dt, p)
}

/// State after `dt` seconds clamped to `[0, duration]`: the law taken once for both (a track's
/// samples and the event loop's current states come here).
pub fn state_at_clamped(s: &BallState, dt: f64, p: &Params) -> BallState {
    let l = law(s, p);
    evolve(s, &l, dt.clamp(0.0, held(&l, p)), p)
}

/// State after `dt` seconds under law `l` taken at `s`.
fn evolve(s: &BallState, l: &Law, dt: f64, p: &Params) -> BallState {
    let (uhat, f) = (l.uhat, l.mu * p.g);
    let mut out = *s;
    out.pos = s.pos + s.vel * dt + 0.5 * dt * dt * (l.extra - f * uhat);
    out.vel = s.vel + dt * (l.extra - f * uhat);
    let dw = (INV_INERTIA_FACTOR * f / p.ball_radius * dt) * Vec3::z().cross(&uhat);
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
