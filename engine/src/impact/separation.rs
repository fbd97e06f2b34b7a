//! The smallest separation speed after an impact, and the push that gives it.
//!
//! A ball pressed against another ball (or a cushion) by its own acceleration meets it again
//! and again, each bounce slower (restitution below 1 and the cloth's friction after each
//! impact), infinitely often in a finite time: the series converges to a sustained contact,
//! which no polynomial law describes. Following the impulse-based treatment of resting contact
//! (Mirtich and Canny 1995), an impact that leaves the bodies separating slower than
//! [`MIN_SEPARATION`] gets an extra normal impulse through the centres that makes them separate
//! at exactly that speed. A sustained contact thus becomes a steady train of micro-collisions
//! whose impulses average to the contact force, the bodies never more than a few micrometres
//! apart. The price is bounded: the push adds 1/2 m_eff (MIN_SEPARATION^2 - s^2) to an impact
//! that left the bodies separating at s >= 0, at most 1/2 m_eff MIN_SEPARATION^2 — for the
//! thesis's ball mass, 3.5e-8 J for two balls (m_eff = M/2), 7.0e-8 J for a ball against a
//! cushion (m_eff = M); it scales with the mass of a scene's balls — which the
//! cloth's friction then removes. The impact itself is solved with the model's own
//! restitution, so its energy balance is the model's.

use crate::ball::{BallState, Vec3};
use crate::motion::ON_CLOTH;
use crate::params::Params;

/// Smallest separation speed after an impact, m/s.
pub const MIN_SEPARATION: f64 = 1e-3;

/// An approach slower than this (m/s) is a grazing touch, not an impact to solve: its impulse,
/// at most (1 + e) m_eff v_n along the normal and mu times that across it, changes no
/// velocity by more than a few times 1e-7 m/s, a ten-thousandth of the [`MIN_SEPARATION`] push
/// that follows it. The touch is that push alone. The frictional solver, which scales the
/// impact by its approach speed, could not resolve such a touch anyway: a ball moving along a
/// cushion that it meets at 4e-17 m/s (found by the fuzz harness, a ball frozen to a cushion
/// and struck along it) has slips 1e16 times that speed.
pub const GRAZING_APPROACH: f64 = 1e-7;

/// An approach at most this (m/s) is a micro-collision of a resting contact, not a new impact:
/// it lifts no ball off the cloth. A ball pressed into another by its own acceleration parts
/// from it at [`MIN_SEPARATION`] and comes back at about that speed (the pressing acceleration
/// turns it round as it sent it off), again and again: the train stands for a sustained contact
/// force N, whose friction could lift a ball only if mu_bb N exceeded its weight, and the cloth's
/// friction, which presses the balls together, cannot do that. The hop the impact model gives
/// such a touch (thesis §6.1.6: the ball-ball friction's vertical pull on the ball it does not
/// press down) is at most mu_bb (1 + e) / 2 of the approach, 2 mm/s at most, rising less than
/// 0.2 µm (at g = 9.81 m/s²) for less than 0.4 ms: below the cloth's texture and anything
/// measured, and as many events again (a lift-off and a landing) for each micro-collision.
/// Twice the floor, so that a train's approaches, a little above it when the accelerations
/// change between touches, count too.
pub const RESTING_APPROACH: f64 = 2.0 * MIN_SEPARATION;

/// Keeps on the cloth a ball that was on it before a resting contact's micro-collision
/// ([`RESTING_APPROACH`]): its upward velocity is taken by the cloth, as at a landing (thesis
/// §6.1.6: the cloth's vertical percussion; its friction percussion neglected).
pub fn stay_on_cloth(after: &mut BallState, before: &BallState, p: &Params) {
    if before.pos.z <= p.ball_radius + ON_CLOTH && after.vel.z > 0.0 {
        after.vel.z = 0.0;
    }
}

/// Pushes balls `a` and `b` (equal masses) apart along `n`, the unit vector from `a`'s centre
/// to `b`'s, so that they separate at [`MIN_SEPARATION`] at least.
pub fn separate_balls(a: &mut BallState, b: &mut BallState, n: Vec3) {
    let s = (b.vel - a.vel).dot(&n);
    if s < MIN_SEPARATION {
        let dv = 0.5 * (MIN_SEPARATION - s) * n;
        a.vel -= dv;
        b.vel += dv;
    }
}

/// Pushes `ball` away from a fixed body along `away` (unit, from the body towards the ball) so
/// that it separates at [`MIN_SEPARATION`] at least.
pub fn separate_from_fixed(ball: &mut BallState, away: Vec3) {
    let s = ball.vel.dot(&away);
    if s < MIN_SEPARATION {
        ball.vel += (MIN_SEPARATION - s) * away;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Motion;

    fn ball(vel: Vec3) -> BallState {
        BallState {
            pos: Vec3::zeros(),
            vel,
            spin: Vec3::zeros(),
            motion: Motion::Sliding,
        }
    }

    #[test]
    fn slow_separations_are_raised_to_the_floor_and_no_further() {
        let n = Vec3::x();
        let (mut a, mut b) = (
            ball(Vec3::new(0.3, 0.2, 0.0)),
            ball(Vec3::new(0.3, -0.1, 0.0)),
        );
        separate_balls(&mut a, &mut b, n);
        assert!(((b.vel - a.vel).dot(&n) - MIN_SEPARATION).abs() < 1e-15);
        // Momentum is kept, the tangential velocities untouched.
        assert!((a.vel + b.vel - Vec3::new(0.6, 0.1, 0.0)).norm() < 1e-15);
        assert_eq!((a.vel.y, b.vel.y), (0.2, -0.1));
        let (mut a, mut b) = (ball(Vec3::zeros()), ball(Vec3::new(0.5, 0.0, 0.0)));
        separate_balls(&mut a, &mut b, n);
        assert_eq!((a.vel, b.vel), (Vec3::zeros(), Vec3::new(0.5, 0.0, 0.0)));
        let mut c = ball(Vec3::new(1.0, 0.0, 0.0));
        separate_from_fixed(&mut c, Vec3::y());
        assert_eq!(c.vel, Vec3::new(1.0, MIN_SEPARATION, 0.0));
    }
}
