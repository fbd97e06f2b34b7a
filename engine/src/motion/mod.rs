//! Closed-form motion between events: one law per [`Motion`] phase, each giving the state at
//! any time, its position polynomial and the time at which it ends.

pub mod airborne;
pub mod bed;
pub mod cloth;
pub mod rolling;
pub mod sliding;
pub mod spinning;

use crate::ball::{BallState, Motion, ROLLING_SHARE, ROLLING_SPIN_SHARE, Vec3};
use crate::params::Params;
use serde::{Deserialize, Serialize};

/// Speed below which a ball counts as at rest, m/s. Far below anything a camera or a player
/// could see; it only absorbs rounding (a ball left at 1e-9 m/s would stop within 1 ns).
pub const REST_SPEED: f64 = 1e-9;
/// Contact slip below which a ball on the cloth counts as rolling, m/s.
pub const ROLL_SLIP: f64 = 1e-9;
/// Sidespin below which a ball counts as not spinning, rad/s.
pub const REST_SPIN: f64 = 1e-9;
/// Height above the resting height below which a ball counts as on the cloth, m.
pub const ON_CLOTH: f64 = 1e-12;

/// A ball's centre as a polynomial in the time tau since its reference:
/// `pos(tau) = c + b tau + a tau^2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Path {
    /// Position at tau = 0.
    pub c: Vec3,
    /// Velocity at tau = 0.
    pub b: Vec3,
    /// Half the (constant) acceleration.
    pub a: Vec3,
}

impl Path {
    /// Position at `tau`.
    pub fn at(&self, tau: f64) -> Vec3 {
        self.c + (self.b + self.a * tau) * tau
    }

    /// Velocity at `tau`.
    pub fn velocity(&self, tau: f64) -> Vec3 {
        self.b + 2.0 * tau * self.a
    }

    /// The path of `self` relative to `other` (both from the same instant).
    pub fn minus(&self, other: &Path) -> Path {
        Path {
            c: self.c - other.c,
            b: self.b - other.b,
            a: self.a - other.a,
        }
    }

    /// The same path with its vertical part dropped (plan view).
    pub fn plan(&self) -> Path {
        let flat = |v: Vec3| Vec3::new(v.x, v.y, 0.0);
        Path {
            c: flat(self.c),
            b: flat(self.b),
            a: flat(self.a),
        }
    }

    /// Largest distance the centre can move from `c` within `tau` (a bound for culling).
    pub fn reach(&self, tau: f64) -> f64 {
        self.b.norm() * tau + self.a.norm() * tau * tau
    }

    /// A lower bound on the distance of the centre from the origin over [0, `tau`] (for
    /// culling): the distance of the chord from `at(0)` to `at(tau)`, less the path's largest
    /// departure from its chord, `|a| tau^2 / 4` (the path minus its chord is `a t (t - tau)`).
    pub fn clearance(&self, tau: f64) -> f64 {
        let (p0, p1) = (self.c, self.at(tau));
        let chord = p1 - p0;
        let len2 = chord.norm_squared();
        let s = if len2 > 0.0 {
            (-p0.dot(&chord) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (p0 + chord * s).norm() - self.a.norm() * tau * tau / 4.0
    }

    /// Size of the numbers in the path over [0, `tau`], m: the scale of its rounding errors.
    pub fn size(&self, tau: f64) -> f64 {
        self.c.norm() + self.reach(tau)
    }
}

/// What ends a motion law.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Transition {
    /// Sliding ended with the ball moving: it rolls.
    SlideToRoll,
    /// Sliding ended with the centre at rest but sidespin left.
    SlideToSpin,
    /// Sliding ended with the ball fully at rest.
    SlideToStop,
    /// Rolling ended with sidespin left.
    RollToSpin,
    /// Rolling ended with the ball at rest.
    RollToStop,
    /// Sidespin of a resting ball decayed to zero.
    SpinToStop,
    /// An airborne ball came back down onto the cloth (and, with the bed's restitution
    /// `e_bed`, bounced: it leaves the bed again at once, [`bed`]).
    Landing,
    /// A segment of a law with the effects of [`cloth`] on ended and the law's accelerations
    /// were renewed; the motion phase is unchanged. Not reported as an event.
    Refresh,
}

impl Transition {
    /// Every transition, in declaration order.
    pub const ALL: [Transition; 8] = [
        Transition::SlideToRoll,
        Transition::SlideToSpin,
        Transition::SlideToStop,
        Transition::RollToSpin,
        Transition::RollToStop,
        Transition::SpinToStop,
        Transition::Landing,
        Transition::Refresh,
    ];

    /// The event kind name used in the JSON result.
    pub fn name(self) -> &'static str {
        match self {
            Transition::SlideToRoll => "slide_to_roll",
            Transition::SlideToSpin => "slide_to_spin",
            Transition::SlideToStop => "slide_to_stop",
            Transition::RollToSpin => "roll_to_spin",
            Transition::RollToStop => "roll_to_stop",
            Transition::SpinToStop => "spin_to_stop",
            Transition::Landing => "landing",
            Transition::Refresh => "refresh",
        }
    }
}

/// State after `dt` seconds under the law of `s.motion` (dt is clamped to the law's duration).
pub fn state_at(s: &BallState, dt: f64, p: &Params) -> BallState {
    match s.motion {
        Motion::Sliding => sliding::state_at_clamped(s, dt, p),
        Motion::Rolling => rolling::state_at_clamped(s, dt, p),
        Motion::Spinning => spinning::state_at(s, dt.clamp(0.0, duration(s, p)), p),
        Motion::Airborne => airborne::state_at(s, dt.clamp(0.0, duration(s, p)), p),
        Motion::Stationary | Motion::Pocketed | Motion::OffTable => *s,
    }
}

/// How long the current law holds, s (infinite for a ball at rest or pocketed).
pub fn duration(s: &BallState, p: &Params) -> f64 {
    match s.motion {
        Motion::Sliding => sliding::duration(s, p),
        Motion::Rolling => rolling::duration(s, p),
        Motion::Spinning => spinning::duration(s, p),
        Motion::Airborne => airborne::duration(s, p),
        Motion::Stationary | Motion::Pocketed | Motion::OffTable => f64::INFINITY,
    }
}

/// The centre's position polynomial under the current law.
pub fn path(s: &BallState, p: &Params) -> Path {
    let acc = match s.motion {
        Motion::Sliding => sliding::acceleration(s, p),
        Motion::Rolling => rolling::acceleration(s, p),
        Motion::Airborne => airborne::acceleration(p),
        Motion::Spinning | Motion::Stationary | Motion::Pocketed | Motion::OffTable => {
            Vec3::zeros()
        }
    };
    path_with(s, acc)
}

/// [`duration`] and [`path`] together: the law is taken once (the event loop needs both at
/// every law's start, with the cloth's effects on every few millimetres).
pub fn duration_and_path(s: &BallState, p: &Params) -> (f64, Path) {
    let (duration, acc) = match s.motion {
        Motion::Sliding => sliding::duration_and_acceleration(s, p),
        Motion::Rolling => rolling::duration_and_acceleration(s, p),
        _ => return (duration(s, p), path(s, p)),
    };
    (duration, path_with(s, acc))
}

/// The position polynomial of `s` under acceleration `acc`.
fn path_with(s: &BallState, acc: Vec3) -> Path {
    let vel = if s.motion.is_moving() {
        s.vel
    } else {
        Vec3::zeros()
    };
    Path {
        c: s.pos,
        b: vel,
        a: 0.5 * acc,
    }
}

/// The transition that ends the law that started from `start`, applied to `end` (the state
/// evaluated at the law's end): returns its kind and the state the next law starts from.
/// Returns `None` for laws that never end (rest, pocketed).
pub fn finish(start: &BallState, end: &BallState, p: &Params) -> Option<(Transition, BallState)> {
    let mut s = *end;
    let segment_end = match end.motion {
        Motion::Sliding => !sliding::ends_rolling(start, p),
        Motion::Rolling => !rolling::ends_stopped(start, p),
        _ => false,
    };
    if segment_end {
        let next = settle_on_cloth(s, p);
        if next.motion == end.motion {
            return Some((Transition::Refresh, next));
        }
    }
    let kind = match end.motion {
        Motion::Sliding => {
            if cloth::active(p) {
                // The slip along its starting direction is used up, but the bed and nap may
                // have left a sliver across it: end it as the cloth would, keeping the angular
                // momentum about the contact point (v = 5/7 v + 2/7 R w x e_z).
                let r = p.ball_radius;
                let v = ROLLING_SHARE * s.vel + ROLLING_SPIN_SHARE * r * s.spin.cross(&Vec3::z());
                s.vel = Vec3::new(v.x, v.y, 0.0);
                let w = Vec3::z().cross(&s.vel) / r;
                s.spin.x = w.x;
                s.spin.y = w.y;
            }
            s = settle_on_cloth(s, p);
            match s.motion {
                Motion::Rolling => Transition::SlideToRoll,
                Motion::Spinning => Transition::SlideToSpin,
                // The slip can only vanish on the cloth, so the ball rolls or rests.
                _ => Transition::SlideToStop,
            }
        }
        Motion::Rolling => {
            s.vel = Vec3::zeros();
            s.spin.x = 0.0;
            s.spin.y = 0.0;
            s = settle_on_cloth(s, p);
            if s.motion == Motion::Spinning {
                Transition::RollToSpin
            } else {
                Transition::RollToStop
            }
        }
        Motion::Spinning => {
            s.spin = Vec3::zeros();
            s.motion = Motion::Stationary;
            Transition::SpinToStop
        }
        Motion::Airborne => {
            // Thesis §6.1.6: the cloth's vertical percussion stops the fall; its friction
            // percussion (mu_s times a small impulse) is neglected. With `e_bed` the bed gives
            // back part of the fall ([`bed`]): the ball bounces, still in the air.
            s.pos.z = p.ball_radius;
            let up = bed::rebound(-s.vel.z, p);
            if up > 0.0 {
                s.vel.z = up;
            } else {
                s.vel.z = 0.0;
                s = settle_on_cloth(s, p);
            }
            Transition::Landing
        }
        Motion::Stationary | Motion::Pocketed | Motion::OffTable => return None,
    };
    Some((kind, s))
}

/// Assigns the law a ball on the cloth follows: it rests, spins, rolls or slides.
/// Velocities below the rest thresholds are set to zero and a slip below [`ROLL_SLIP`] is
/// removed by setting the spin to exact rolling, so the next law starts clean.
pub fn settle_on_cloth(mut s: BallState, p: &Params) -> BallState {
    let r = p.ball_radius;
    s.pos.z = r;
    s.vel.z = 0.0;
    let speed = s.vel.norm();
    let slip = s.slip(r).norm();
    if speed <= REST_SPEED && slip <= ROLL_SLIP {
        s.vel = Vec3::zeros();
        s.spin.x = 0.0;
        s.spin.y = 0.0;
        if s.spin.z.abs() <= REST_SPIN {
            s.spin.z = 0.0;
            s.motion = Motion::Stationary;
        } else {
            s.motion = Motion::Spinning;
        }
    } else if slip <= ROLL_SLIP {
        let w = Vec3::z().cross(&s.vel) / r;
        s.spin.x = w.x;
        s.spin.y = w.y;
        s.motion = Motion::Rolling;
    } else {
        s.motion = Motion::Sliding;
    }
    s
}

/// Assigns the law for any ball in play: airborne if it is above the cloth or rising,
/// otherwise as [`settle_on_cloth`] (a downward velocity on the cloth is stopped by the cloth).
pub fn settle(s: BallState, p: &Params) -> BallState {
    if !s.motion.in_play() {
        return s;
    }
    let above = s.pos.z - p.ball_radius > ON_CLOTH;
    if above || s.vel.z > REST_SPEED {
        let mut s = s;
        s.motion = Motion::Airborne;
        if !above {
            s.pos.z = p.ball_radius;
        }
        return s;
    }
    settle_on_cloth(s, p)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ball(vel: Vec3, spin: Vec3, p: &Params) -> BallState {
        settle(
            BallState {
                pos: Vec3::new(1.0, 1.0, p.ball_radius),
                vel,
                spin,
                motion: Motion::Stationary,
            },
            p,
        )
    }

    #[test]
    fn classification() {
        let p = Params::default();
        let r = p.ball_radius;
        assert_eq!(
            ball(Vec3::zeros(), Vec3::zeros(), &p).motion,
            Motion::Stationary
        );
        assert_eq!(
            ball(Vec3::zeros(), Vec3::new(0.0, 0.0, 3.0), &p).motion,
            Motion::Spinning
        );
        assert_eq!(ball(Vec3::x(), Vec3::zeros(), &p).motion, Motion::Sliding);
        assert_eq!(ball(Vec3::x(), Vec3::y() / r, &p).motion, Motion::Rolling);
        // A ball at rest with topspin slides (it will accelerate).
        assert_eq!(
            ball(Vec3::zeros(), Vec3::y() * 10.0, &p).motion,
            Motion::Sliding
        );
        assert_eq!(
            ball(Vec3::new(1.0, 0.0, 0.1), Vec3::zeros(), &p).motion,
            Motion::Airborne
        );
    }

    #[test]
    fn path_matches_state_at() {
        let p = Params::default();
        for s in [
            ball(Vec3::new(1.0, 0.3, 0.0), Vec3::new(5.0, 40.0, -7.0), &p),
            ball(
                Vec3::new(-0.5, 0.8, 0.0),
                Vec3::new(-0.8, -0.5, 0.0) / p.ball_radius,
                &p,
            ),
            ball(Vec3::new(1.0, 0.0, 0.3), Vec3::new(1.0, 2.0, 3.0), &p),
        ] {
            let path = path(&s, &p);
            let t = 0.7 * duration(&s, &p).min(1.0);
            let e = state_at(&s, t, &p);
            assert!((path.at(t) - e.pos).norm() < 1e-14, "{:?}", s.motion);
            assert!((path.velocity(t) - e.vel).norm() < 1e-14);
        }
    }

    #[test]
    fn overspin_accelerates_until_rolling() {
        // Rolling speed from any sliding state: 5/7 v0 + 2/7 R (w0 x e_z) (peers.md).
        let p = Params::default();
        let v0 = Vec3::new(0.5, 0.0, 0.0);
        let w0 = Vec3::new(0.0, 60.0, 0.0);
        let s = ball(v0, w0, &p);
        let (kind, e) = finish(&s, &state_at(&s, duration(&s, &p), &p), &p).unwrap();
        assert_eq!(kind, Transition::SlideToRoll);
        let expect = 5.0 / 7.0 * v0 + 2.0 / 7.0 * p.ball_radius * w0.cross(&Vec3::z());
        assert!((e.vel - expect).norm() < 1e-12);
        assert!(e.vel.x > v0.x);
    }

    #[test]
    fn a_pure_stop_shot_ends_at_rest() {
        // Backspin exactly cancelling: v_final = 5/7 v0 - 2/7 R w = 0.
        let p = Params::default();
        let v0 = 1.0;
        let w = -2.5 * v0 / p.ball_radius;
        let s = ball(Vec3::new(v0, 0.0, 0.0), Vec3::new(0.0, w, 20.0), &p);
        let (kind, e) = finish(&s, &state_at(&s, duration(&s, &p), &p), &p).unwrap();
        assert_eq!(kind, Transition::SlideToSpin);
        assert_eq!(e.vel, Vec3::zeros());
        assert_eq!(e.motion, Motion::Spinning);
    }
}
