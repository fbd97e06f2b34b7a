//! Random impacts and the impact solvers' convergence on them, for the convergence tests
//! (`engine/tests/impact_models.rs`, which bound the error) and
//! `engine/examples/impact_sweep.rs` (which prints its distribution). Snooker's frictions and
//! beyond: mu_bb and mu_w up to 0.3, cloth friction up to 0.3, restitution 0.5-1, speeds
//! 0.05-6 m/s, cuts and incidences of 1-83 degrees, topspin and sidespin up to 2 V/R.

use super::ball_ball::mathavan as bb;
use super::cushion::mathavan as cush;
use super::impulse::{Impact, Kinematics};
use super::incoming;
use crate::ball::Vec3;
use crate::params::Params;
pub use crate::rng::Rng;

/// Seed of the sweeps (the test's and the example's: the same impacts).
pub const SEED: u64 = 0x1234_5678_9abc_def1;

/// Tolerance of the converged solutions the others are compared with.
pub const CONVERGED: f64 = 1e-13;

/// One impact: what it is, its contact problem and velocities, and its speed V (m/s).
pub struct RandomImpact {
    /// Speed, angle, spins and coefficients, for people.
    pub text: String,
    /// The Mathavan contact problem.
    pub contact: Impact,
    /// Velocities before the impact.
    pub kin: Kinematics,
    /// The approach speed, m/s.
    pub speed: f64,
}

/// A random ball-ball impact (a cue ball moving along +x, a red at rest at the cut angle) or
/// ball-cushion impact (a ball meeting the cushion along y = 0 at the incidence angle).
pub fn random_impact(rng: &mut Rng, cushion: bool) -> RandomImpact {
    let [v, angle, k, m, mu, e, ms] = [
        (0.05, 6.0),
        (0.02, 1.45),
        (-2.0, 2.0),
        (-2.0, 2.0),
        (0.0, 0.3),
        (0.5, 1.0),
        (0.0, 0.3),
    ]
    .map(|(a, b)| rng.uniform(a, b));
    let p = Params {
        mu_ball: mu,
        e_ball: e,
        mu_cushion: mu,
        e_cushion: e,
        mu_slide: ms,
        ..Params::default()
    };
    let text = format!(
        "v {v:.3} m/s, angle {:.1} deg, topspin {k:.3}, sidespin {m:.3}, mu {mu:.3}, e {e:.3}, mu_s {ms:.3}",
        angle.to_degrees()
    );
    let (contact, kin) = if cushion {
        let s = incoming::cushion(v, angle, k, m, &p);
        let kin = Kinematics {
            vel: [s.vel, Vec3::zeros()],
            spin: [s.spin, Vec3::zeros()],
        };
        (cush::contact(&s, Vec3::y(), &p), kin)
    } else {
        let (cue, red) = incoming::ball_ball(v, angle, k, m, &p);
        let kin = Kinematics {
            vel: [cue.vel, red.vel],
            spin: [cue.spin, red.spin],
        };
        (bb::contact(&cue, &red, &p), kin)
    };
    RandomImpact {
        text,
        contact,
        kin,
        speed: v,
    }
}

/// Largest difference between two outcomes over both bodies' velocities and spins (as R w),
/// as a fraction of `scale` (m/s); `r` is the ball radius.
pub fn difference(a: &Kinematics, b: &Kinematics, scale: f64, r: f64) -> f64 {
    (0..2)
        .map(|i| {
            let dv = (a.vel[i] - b.vel[i]).norm();
            let dw = (a.spin[i] - b.spin[i]).norm() * r;
            dv.max(dw) / scale
        })
        .fold(0.0, f64::max)
}

/// The impact solved at tolerance `tol`: its difference from the converged solution (a
/// fraction of V) and the integration steps it took.
pub fn convergence(impact: &RandomImpact, tol: f64) -> (f64, usize) {
    let p = Params::default();
    let (r, mass) = (p.ball_radius, p.ball_mass);
    let c = &impact.contact;
    let fine = c.solve_to(&impact.kin, r, mass, CONVERGED, None).unwrap();
    let out = c.solve_to(&impact.kin, r, mass, tol, None).unwrap();
    (
        difference(&out.after, &fine.after, impact.speed, r),
        out.steps,
    )
}
