//! Random impacts and the impact solvers' convergence on them, shared by
//! `tests/impact_models.rs` (which bounds the error) and `engine/examples/impact_sweep.rs`
//! (which prints its distribution). Snooker's frictions and beyond: mu_bb and mu_w up to 0.3,
//! cloth friction up to 0.3, restitution 0.5-1, speeds 0.05-6 m/s, cuts and incidences of
//! 1-83 degrees, topspin and sidespin up to 2 V/R.
#![allow(dead_code)]

use snooker_engine::impact::ball_ball::mathavan as bb;
use snooker_engine::impact::cushion::mathavan as cush;
use snooker_engine::impact::impulse::{Contact, Kinematics};
use snooker_engine::{BallState, Motion, Params, Vec3};

/// Seed of the sweeps (the test's and the example's: the same impacts).
pub const SEED: u64 = 0x1234_5678_9abc_def1;

/// Tolerance of the converged solutions the others are compared with.
pub const CONVERGED: f64 = 1e-13;

/// A small deterministic generator of uniform numbers (xorshift).
pub struct Rng(pub u64);

impl Rng {
    /// Uniform in [a, b).
    pub fn uniform(&mut self, a: f64, b: f64) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        a + (b - a) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }
}

/// The thesis's ball-ball set-up (§6.1.4.1) in the table frame: the cue ball moves along +x
/// at `v`, the object ball sits at cut angle `cut` (line of centres at `cut` from +x, to the
/// left); topspin `k` V/R about the axis of rolling, sidespin `m` V/R about +z.
pub fn pair(v: f64, cut: f64, k: f64, m: f64, p: &Params) -> (BallState, BallState) {
    let r = p.ball_radius;
    let cue = BallState {
        pos: Vec3::new(0.0, 0.0, r),
        vel: Vec3::new(v, 0.0, 0.0),
        spin: Vec3::new(0.0, k * v / r, m * v / r),
        motion: Motion::Sliding,
    };
    let obj = BallState::at_rest(2.0 * r * cut.cos(), 2.0 * r * cut.sin(), r);
    (cue, obj)
}

/// A ball meeting the cushion along y = 0 (plan normal +y) at `incidence` from the cushion
/// line, with topspin `k` V/R (1 = rolling) and sidespin `m` V/R.
pub fn at_cushion(v: f64, incidence: f64, k: f64, m: f64, p: &Params) -> BallState {
    let r = p.ball_radius;
    let vel = v * Vec3::new(incidence.cos(), -incidence.sin(), 0.0);
    let roll = Vec3::z().cross(&vel) / r;
    BallState {
        pos: Vec3::new(1.0, p.cushion_contact_distance(), r),
        vel,
        spin: k * roll + Vec3::new(0.0, 0.0, m * v / r),
        motion: Motion::Sliding,
    }
}

/// One impact: what it is, its contact problem and velocities, and its speed V (m/s).
pub struct Impact {
    /// Speed, angle, spins and coefficients, for people.
    pub text: String,
    /// The Mathavan contact problem.
    pub contact: Contact,
    /// Velocities before the impact.
    pub kin: Kinematics,
    /// The approach speed, m/s.
    pub speed: f64,
}

/// A random ball-ball impact (a cue ball moving along +x, a red at rest at the cut angle) or
/// ball-cushion impact (a ball meeting the cushion along y = 0 at the incidence angle).
pub fn random_impact(rng: &mut Rng, cushion: bool) -> Impact {
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
        let s = at_cushion(v, angle, k, m, &p);
        let kin = Kinematics {
            vel: [s.vel, Vec3::zeros()],
            spin: [s.spin, Vec3::zeros()],
        };
        (cush::contact(&s, Vec3::y(), &p), kin)
    } else {
        let (cue, red) = pair(v, angle, k, m, &p);
        let kin = Kinematics {
            vel: [cue.vel, red.vel],
            spin: [cue.spin, red.spin],
        };
        (bb::contact(&cue, &red, &p), kin)
    };
    Impact {
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
pub fn convergence(impact: &Impact, tol: f64) -> (f64, usize) {
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
