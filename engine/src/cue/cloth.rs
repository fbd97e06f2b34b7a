//! The cloth's friction percussion during the cue strike (de la Torre Juarez 1994, in thesis
//! §2.4.1.1), an effect beyond the thesis's strike, off by default (`mu_strike_cloth` = 0).
//!
//! A cue inclined by `e` drives the ball into the cloth: the cloth's normal impulse is the
//! downward part of the cue's, N = J sin(e), and while it acts the cloth's friction opposes the
//! slip of the ball's bottom point with at most `mu_strike_cloth` N. The thesis neglects it
//! (§7.1.3: 2 % of the cue force at its robot's 6.5°, after de la Torre Juarez); on a massé
//! cue at 60° it is 18 % at mu = 0.21, and a centre strike steeper than atan(1 / 3.5 mu) leaves
//! rolling (53.7° at mu = 0.21).
//!
//! Model: the cue's, the cloth's normal and the cloth's friction impulses grow together over
//! the strike (a progress s from 0 to 1; the common assumption of percussion analyses, the
//! thesis's §6 with the normal impulse as its variable). A horizontal impulse F at the bottom
//! point changes the slip by F (1/M + R^2/I) = 7F / 2M, so the slip u obeys
//! du/ds = a - k u/|u|, where `a` is what the cue alone adds to the slip over the strike and
//! k = 7 mu N / 2M the most the friction can take off it; at u = 0 the cloth holds the ball
//! (static friction) while |a| <= k. From rest the slip keeps the direction of `a` throughout
//! (de la Torre Juarez's constant-direction solution); a ball struck as it slides turns its
//! slip towards `a` on the way, solved here in closed form (the sliding block on an inclined
//! plane's equation): with phi the angle of u from a, t = tan(phi / 2) and lambda = k / |a|,
//! |u| = |u0| (t / t0)^(lambda - 1) (1 + t^2) / (1 + t0^2) and
//! s = |u0| / (|a| (1 + t0^2)) [(1 - (t/t0)^(lambda-1)) / (lambda-1) + t0^2 (1 - (t/t0)^(lambda+1)) / (lambda+1)],
//! whose s = 1 is found by bisection on ln t. The cue's impulse itself is the thesis's
//! (§7.1.3): the friction's feedback on the size of the cue's impulse is neglected.

use crate::ball::{BallState, SLIP_RATE_FACTOR, Vec3};
use crate::params::Params;

/// Below this sine of the angle between the starting slip and the cue's, the two are taken as
/// parallel (the one-dimensional solution; the closed form's t0 would overflow).
const PARALLEL_SINE: f64 = 1e-12;

/// The horizontal friction impulse the cloth gives a ball during a strike, N s: `before` is
/// the ball as struck, `struck` the ball after the cue's impulse alone, `normal` the cloth's
/// normal impulse (the downward part of the cue's). None when there is no friction to give
/// (`mu_strike_cloth` or `normal` zero), so that a level cue's strike is the thesis's to the bit.
pub fn percussion(before: &BallState, struck: &BallState, normal: f64, p: &Params) -> Option<Vec3> {
    if p.mu_strike_cloth <= 0.0 || normal <= 0.0 {
        return None;
    }
    let r = p.ball_radius;
    let u0 = before.slip(r);
    let a = struck.slip(r) - u0;
    let k = SLIP_RATE_FACTOR * p.mu_strike_cloth * normal / p.ball_mass;
    let u1 = final_slip(u0, a, k);
    // u1 = u0 + a + (7/2M) F.
    Some((u1 - u0 - a) * (p.ball_mass / SLIP_RATE_FACTOR))
}

/// Applies a horizontal impulse `f` at the bottom point of `ball` (the cloth's contact).
pub fn apply(ball: &BallState, f: Vec3, p: &Params) -> BallState {
    let mut out = *ball;
    out.vel += f / p.ball_mass;
    out.spin += Vec3::new(0.0, 0.0, -p.ball_radius).cross(&f) / p.inertia();
    out
}

/// The slip at the end of a percussion that adds `a` to the slip `u0` while friction of at
/// most `k` (over the whole percussion) opposes it: the solution at s = 1 of
/// du/ds = a - k u/|u| (module docs). Horizontal vectors (z ignored, 0 in the result).
pub fn final_slip(u0: Vec3, a: Vec3, k: f64) -> Vec3 {
    let u0 = Vec3::new(u0.x, u0.y, 0.0);
    let a = Vec3::new(a.x, a.y, 0.0);
    let (r0, big_a) = (u0.norm(), a.norm());
    if k <= 0.0 {
        return u0 + a;
    }
    if r0 == 0.0 {
        // From rest in slip: the cloth holds while the cue asks no more than it can give.
        return if big_a <= k {
            Vec3::zeros()
        } else {
            a * (1.0 - k / big_a)
        };
    }
    if big_a == 0.0 {
        return u0 * (1.0 - k / r0).max(0.0);
    }
    let along = a / big_a;
    let (cos0, sin0) = (u0.dot(&along) / r0, along.cross(&u0).z / r0);
    if sin0.abs() <= PARALLEL_SINE {
        return along * along_line(u0.dot(&along), big_a, k);
    }
    // The perpendicular's side, kept: the slip turns towards `a` without crossing it.
    let across = Vec3::z().cross(&along) * sin0.signum();
    let lambda = k / big_a;
    let phi0 = sin0.abs().atan2(cos0);
    let t0 = (0.5 * phi0).tan();
    let scale = r0 / (big_a * (1.0 + t0 * t0));
    // Progress s reached when ln(t / t0) has fallen to rho (< 0).
    let progress = |rho: f64| {
        let first = if lambda == 1.0 {
            -rho
        } else {
            -((lambda - 1.0) * rho).exp_m1() / (lambda - 1.0)
        };
        scale * (first - t0 * t0 * ((lambda + 1.0) * rho).exp_m1() / (lambda + 1.0))
    };
    if lambda > 1.0 {
        // The slip reaches zero at a finite progress and the cloth holds it there.
        let stick = scale * (1.0 / (lambda - 1.0) + t0 * t0 / (lambda + 1.0));
        if stick <= 1.0 {
            return Vec3::zeros();
        }
    }
    // Bracket s = 1, then bisect (s grows as rho falls; deterministic to the last bit).
    // Where the slip barely reaches zero (stick within rounding of 1) the bracket can stop at
    // -1e300, where the slip is zero to the last bit.
    let mut lo = -1.0;
    while progress(lo) < 1.0 && lo > -1e300 {
        lo *= 2.0;
    }
    let mut hi = 0.0;
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if progress(mid) < 1.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let rho = 0.5 * (lo + hi);
    let t1 = t0 * rho.exp();
    let r1 = r0 * ((lambda - 1.0) * rho).exp() * (1.0 + t1 * t1) / (1.0 + t0 * t0);
    let phi1 = 2.0 * t1.atan();
    r1 * (phi1.cos() * along + phi1.sin() * across)
}

/// The one-dimensional case: the slip `x0` along the cue's slip `big_a` (> 0), friction `k`.
fn along_line(x0: f64, big_a: f64, k: f64) -> f64 {
    if x0 > 0.0 {
        // With the cue: grows by big_a - k, or falls to zero and is held there.
        if big_a >= k {
            x0 + big_a - k
        } else {
            (x0 + big_a - k).max(0.0)
        }
    } else {
        // Against it: friction and cue both raise it to zero, then it goes on as from rest.
        let to_zero = -x0 / (big_a + k);
        if to_zero >= 1.0 {
            x0 + big_a + k
        } else {
            (big_a - k).max(0.0) * (1.0 - to_zero)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// du/ds = a - k u/|u| by classical Runge-Kutta with fine steps, the cloth holding a slip
    /// that falls to zero while |a| <= k: the closed form's reference.
    fn integrated(u0: Vec3, a: Vec3, k: f64) -> Vec3 {
        let n = 200_000;
        let h = 1.0 / n as f64;
        let rate = |u: Vec3| {
            let r = u.norm();
            if r < 1e-12 {
                if a.norm() <= k {
                    Vec3::zeros()
                } else {
                    a * (1.0 - k / a.norm())
                }
            } else {
                a - u * (k / r)
            }
        };
        let mut u = u0;
        for _ in 0..n {
            if u.norm() <= 1.1 * k * h && a.norm() <= k {
                u = Vec3::zeros();
                continue;
            }
            let k1 = rate(u);
            let k2 = rate(u + 0.5 * h * k1);
            let k3 = rate(u + 0.5 * h * k2);
            let k4 = rate(u + h * k3);
            u += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        }
        u
    }

    #[test]
    fn the_closed_form_follows_the_slip_equation() {
        let cases = [
            // (u0, a, k): friction weaker than the cue, stronger, equal; slip across, against.
            (Vec3::new(0.3, 0.4, 0.0), Vec3::new(1.0, 0.0, 0.0), 0.5),
            (Vec3::new(0.3, -0.4, 0.0), Vec3::new(1.0, 0.2, 0.0), 2.0),
            (Vec3::new(-0.5, 0.1, 0.0), Vec3::new(0.7, 0.0, 0.0), 0.7),
            (Vec3::new(-2.0, 0.5, 0.0), Vec3::new(0.0, 1.5, 0.0), 0.3),
            (Vec3::new(0.05, 0.02, 0.0), Vec3::new(-0.3, 0.9, 0.0), 1.4),
            (Vec3::new(1.0, 0.0, 0.0), Vec3::new(-0.4, 0.0, 0.0), 0.3),
            (Vec3::new(0.0, 0.0, 0.0), Vec3::new(1.0, 1.0, 0.0), 0.6),
            (Vec3::new(0.0, 0.0, 0.0), Vec3::new(1.0, 1.0, 0.0), 2.0),
            (Vec3::new(0.5, 0.5, 0.0), Vec3::zeros(), 0.3),
        ];
        for (u0, a, k) in cases {
            let exact = final_slip(u0, a, k);
            let reference = integrated(u0, a, k);
            assert!(
                (exact - reference).norm() < 1e-6,
                "u0 {u0:?} a {a:?} k {k}: {exact:?} against {reference:?}"
            );
        }
    }

    #[test]
    fn no_friction_adds_the_cue_s_slip_and_friction_only_takes_slip_away() {
        let (u0, a) = (Vec3::new(0.2, -0.1, 0.0), Vec3::new(0.4, 0.9, 0.0));
        assert_eq!(final_slip(u0, a, 0.0), u0 + a);
        // The friction's work on the slip: |u1| never exceeds the frictionless slip's bound,
        // and the friction impulse (u1 - u0 - a) is at most k.
        for k in [0.1, 0.5, 1.0, 3.0] {
            let u1 = final_slip(u0, a, k);
            let friction = u1 - u0 - a;
            assert!(
                friction.norm() <= k * (1.0 + 1e-12),
                "k {k}: {}",
                friction.norm()
            );
            assert!(u1.norm() < (u0 + a).norm());
        }
    }

    #[test]
    fn a_slip_against_the_cue_s_passes_through_zero_and_a_near_parallel_one_follows_it() {
        // Against: friction and cue raise -0.2 at 1.6 to zero by s = 1/8, then it grows at
        // 1 - 0.6 for the remaining 7/8: 0.35.
        let (u0, a) = (Vec3::new(-0.2, 0.0, 0.0), Vec3::new(1.0, 0.0, 0.0));
        assert!((final_slip(u0, a, 0.6) - Vec3::new(0.35, 0.0, 0.0)).norm() < 1e-15);
        // Held: friction stronger than the cue, the slip stops at zero.
        assert_eq!(final_slip(u0, a, 1.5), Vec3::zeros());
        // With the cue, weaker friction: 0.2 + 1 - 0.6.
        assert!((final_slip(-u0, a, 0.6) - Vec3::new(0.6, 0.0, 0.0)).norm() < 1e-15);
        // A slip a hair off the line swings round zero as the line's does.
        for off in [1e-9, -1e-9, 1e-6] {
            let near = final_slip(Vec3::new(-0.2, off, 0.0), a, 0.6);
            assert!(
                (near - Vec3::new(0.35, 0.0, 0.0)).norm() < 1e-5,
                "{off}: {near:?}"
            );
        }
    }

    #[test]
    fn extreme_sizes_give_finite_slips_within_the_friction_s_reach() {
        // A cue speed may be as small as a user likes: the cue's slip subnormal beside a
        // sliding ball's, or the other way round, and friction far beyond either.
        let sizes = [5e-324, 1e-310, 1e-300, 1e-12, 1.0, 1e3, 1e150];
        for &ua in &sizes {
            for &aa in &sizes {
                for &k in &sizes {
                    let (u0, a) = (
                        Vec3::new(0.6 * ua, -0.8 * ua, 0.0),
                        Vec3::new(aa, 0.3 * aa, 0.0),
                    );
                    let u1 = final_slip(u0, a, k);
                    assert!(u1.iter().all(|x| x.is_finite()), "{ua} {aa} {k}: {u1:?}");
                    // The friction's impulse, u1 - u0 - a, is at most k (rounding aside).
                    let f = (u1 - u0 - a).norm();
                    assert!(
                        f <= k * (1.0 + 1e-9) + 1e-9 * (ua + aa),
                        "{ua} {aa} {k}: {f}"
                    );
                }
            }
        }
    }

    #[test]
    fn a_ball_struck_from_rest_keeps_the_direction_of_the_cue_s_slip() {
        let a = Vec3::new(0.6, -0.8, 0.0);
        assert_eq!(final_slip(Vec3::zeros(), a, 0.5), a * 0.5);
        assert_eq!(final_slip(Vec3::zeros(), a, 1.0), Vec3::zeros());
        assert_eq!(final_slip(Vec3::zeros(), a, 1.5), Vec3::zeros());
    }
}
