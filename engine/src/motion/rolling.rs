//! Rolling: no slip at the cloth (v = w x R e_z); rolling resistance decelerates the ball at
//! mu_r g along a straight line (thesis §2.4.2, eq. V = V0 - mu_r g t; mu_r from §5.1.1.1).
//! Sidespin decays on its own ([`super::spinning`]). A force through the centre of a rolling
//! ball (the bed's tilt, the nap, [`super::cloth`]) accelerates it at 5/7 of force / M, the
//! cloth's static friction keeping it rolling; the law then holds its accelerations over
//! short segments.

use super::cloth;
use super::spinning::sidespin_at;
use crate::ball::{BallState, ROLLING_SHARE, Vec3};
use crate::params::Params;

fn direction(s: &BallState) -> Vec3 {
    let v = Vec3::new(s.vel.x, s.vel.y, 0.0);
    let n = v.norm();
    if n > 0.0 { v / n } else { Vec3::zeros() }
}

/// Acceleration with the ball moving along the unit vector `d`.
fn acceleration_along(d: Vec3, p: &Params) -> Vec3 {
    -p.mu_roll * p.g * d + ROLLING_SHARE * cloth::body_acceleration(p, d)
}

/// The law's direction of travel: the starting one, or with the effects of [`cloth`] on the
/// one at the middle of the coming segment (the midpoint rule, second order in its length).
fn law_direction(s: &BallState, p: &Params) -> Vec3 {
    let d0 = direction(s);
    if !cloth::active(p) {
        return d0;
    }
    let a0 = acceleration_along(d0, p);
    let half = 0.5 * end_along(s, d0, a0).min(cloth::SEGMENT);
    let v = s.vel + half * a0;
    let v = Vec3::new(v.x, v.y, 0.0);
    if v.dot(&d0) > 0.0 { v.normalize() } else { d0 }
}

/// Acceleration of the centre while rolling, m/s^2.
pub fn acceleration(s: &BallState, p: &Params) -> Vec3 {
    acceleration_along(law_direction(s, p), p)
}

/// [`duration`] and [`acceleration`] together, the law taken once (each law's start needs both).
pub fn duration_and_acceleration(s: &BallState, p: &Params) -> (f64, Vec3) {
    let d = law_direction(s, p);
    let a = acceleration_along(d, p);
    (held(end_along(s, d, a), p), a)
}

/// Time at which the velocity along `d` is used up under acceleration `a`.
fn end_along(s: &BallState, d: Vec3, a: Vec3) -> f64 {
    let rate = -a.dot(&d);
    if rate > 0.0 {
        s.vel.dot(&d).max(0.0) / rate
    } else {
        f64::INFINITY
    }
}

/// Time at which the speed along the law's direction is used up.
fn natural_end(s: &BallState, p: &Params) -> f64 {
    let d = law_direction(s, p);
    end_along(s, d, acceleration_along(d, p))
}

/// How long this law holds: until the ball stops, |v0| / (mu_r g) (infinite without rolling
/// resistance), or for at most one segment with the effects of [`cloth`] on.
pub fn duration(s: &BallState, p: &Params) -> f64 {
    held(natural_end(s, p), p)
}

/// How long a law whose speed is used up at `end` holds ([`duration`]).
fn held(end: f64, p: &Params) -> f64 {
    if cloth::active(p) {
        end.min(cloth::SEGMENT)
    } else {
        end
    }
}

/// True when the law ends because the ball stops (not at a segment's end).
pub fn ends_stopped(s: &BallState, p: &Params) -> bool {
    !cloth::active(p) || natural_end(s, p) <= cloth::SEGMENT
}

/// State after `dt` seconds of rolling (valid for 0 <= dt <= [`duration`]).
pub fn state_at(s: &BallState, dt: f64, p: &Params) -> BallState {
    evolve(s, acceleration(s, p), dt, p)
}

/// State after `dt` seconds clamped to `[0, duration]`: the law taken once for both (a track's
/// samples and the event loop's current states come here).
pub fn state_at_clamped(s: &BallState, dt: f64, p: &Params) -> BallState {
    let d = law_direction(s, p);
    let a = acceleration_along(d, p);
    evolve(s, a, dt.clamp(0.0, held(end_along(s, d, a), p)), p)
}

/// State after `dt` seconds under the law's acceleration `a`.
fn evolve(s: &BallState, a: Vec3, dt: f64, p: &Params) -> BallState {
    let mut out = *s;
    out.pos = s.pos + s.vel * dt + 0.5 * dt * dt * a;
    out.vel = s.vel + dt * a;
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
