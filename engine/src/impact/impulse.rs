//! Frictional 3D impact dynamics in impulse space, shared by the two Mathavan models
//! (thesis §6.1, §6.2; Mathavan, Jackson and Parkin 2010; Stronge, *Impact Mechanics* 2000).
//!
//! Two rigid bodies meet at a primary contact (ball-ball, or ball-cushion with the cushion a
//! body of zero inverse mass). The normal impulse P at that contact grows monotonically during
//! the impact and is the independent variable. Forces per unit dP:
//! - at the primary contact: the normal impulse along n (from body 0 to body 1), and Coulomb
//!   friction mu against the slip of body 0's contact point relative to body 1's;
//! - at the cloth under each ball that rests on it: a reaction N that keeps the ball's vertical
//!   velocity at zero while the other forces push the ball down (a unilateral constraint: the
//!   ball whose contact is pushed down presses the cloth, the other lifts off, thesis §6.1.2;
//!   for the cushion this gives dP_C = (sin theta + mu_w sin Phi cos theta) dP_I, eq. 6.28),
//!   and friction mu_s N against the cloth slip.
//!
//! Slip directions are free to change during the impact. Friction is Coulomb's law: against
//! the slip while there is one; at zero slip the contact holds if the friction needed is at
//! most mu N, and otherwise creeps out of zero in the one direction its friction leaves
//! growing. The thesis states "no stick" (§6.1.2.1, §6.2.2.1: friction stops when a slip
//! reaches zero); taken literally that is ill-posed whenever other forces keep driving the
//! slip (the friction then flips every instant), and a fixed-step scheme that re-evaluates the
//! slip direction every step (the thesis's own) converges to this law. Where nothing drives a
//! stopped slip, as in most snooker impacts, the two agree.
//!
//! Restitution is energetic (Stronge): compression ends when the normal relative velocity
//! vanishes; the impact ends when the work of the normal impulse, W(P) = integral of v_n dP,
//! reaches (1 - e^2) W(P_c) (thesis eqs. 6.12, 6.38).
//!
//! The equations are integrated adaptively ([`super::dopri`]) in units of the approach speed V,
//! the ball mass M and radius R; every switch (end of compression, a slip stopping, turning or
//! becoming established, a ball pressing or lifting, the end of the impact) is an event
//! located on the integrator's continuous extension.

// Small dense linear algebra reads best with explicit indices.
#![allow(clippy::needless_range_loop)]

mod against_fixed;
mod establish;

use super::dopri::{self, ErrorMeasure, Events, Stop};
use crate::ball::Vec3;
use against_fixed::AgainstFixed;

/// One body of an impact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    /// M / mass (1 for a ball, 0 for a fixed cushion).
    pub inv_mass: f64,
    /// M R^2 / moment of inertia (5/2 for a solid ball, 0 for a fixed cushion).
    pub inv_inertia: f64,
    /// True when the body rests on the cloth at the start (so the cloth can hold it).
    pub on_cloth: bool,
}

impl Body {
    /// A solid ball of the reference mass and radius.
    pub fn ball(on_cloth: bool) -> Body {
        Body {
            inv_mass: 1.0,
            inv_inertia: 2.5,
            on_cloth,
        }
    }

    /// An immovable body (the cushion).
    pub fn fixed() -> Body {
        Body {
            inv_mass: 0.0,
            inv_inertia: 0.0,
            on_cloth: false,
        }
    }
}

/// The geometry and coefficients of an impact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact {
    /// The two bodies.
    pub bodies: [Body; 2],
    /// Unit normal at the primary contact, from body 0 towards body 1.
    pub normal: Vec3,
    /// The primary contact point relative to each body's centre, in units of R.
    pub arm: [Vec3; 2],
    /// Friction at the primary contact.
    pub mu: f64,
    /// Friction at the cloth during the impact.
    pub mu_cloth: f64,
    /// Energetic coefficient of restitution.
    pub e: f64,
}

/// Velocities of the two bodies (m/s, rad/s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kinematics {
    /// Centre velocities.
    pub vel: [Vec3; 2],
    /// Angular velocities.
    pub spin: [Vec3; 2],
}

/// What the impact did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome {
    /// Velocities just after the impact.
    pub after: Kinematics,
    /// Total normal impulse, N s.
    pub impulse: f64,
    /// Normal impulse at the end of compression, N s.
    pub compression_impulse: f64,
    /// Accepted integration steps.
    pub steps: usize,
    /// Phases between switches.
    pub phases: usize,
}

/// One sample of an impact's progress, for plots of slip against impulse (thesis fig. 6.14).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Normal impulse so far, N s.
    pub impulse: f64,
    /// Slip velocity at the primary contact (body 0 relative to body 1), m/s.
    pub slip: Vec3,
    /// Cloth slip of each body, m/s (zero when it does not touch the cloth).
    pub cloth_slip: [Vec3; 2],
    /// Whether the cloth presses on each body (only then does its cloth slip meet friction).
    pub pressed: [bool; 2],
    /// Normal relative velocity (positive approaching), m/s.
    pub normal_velocity: f64,
}

/// An impact that could not be integrated.
#[derive(Clone, Debug, PartialEq)]
pub struct ImpactError(pub String);

impl std::fmt::Display for ImpactError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "impact could not be resolved: {}", self.0)
    }
}

impl std::error::Error for ImpactError {}

/// Tolerance of the integration (scaled units): that of the slips near zero, the velocities'
/// being 30 times larger (the step error measure, `SlipAware`). Results are within 1e-6 of
/// the converged solution over random impacts with frictions up to 0.3 (worst 5.5e-7 in
/// 200,000; tests/impact_models.rs, docs/impact-convergence.md).
pub const TOLERANCE: f64 = 5e-10;
/// Event functions (velocities in units of V) are located to this.
const ROOT_TOLERANCE: f64 = 1e-12;
/// A slip below this many integration tolerances (as a fraction of V) counts as zero: above
/// the integration's noise and the chatter of a contact about to stick (so a nil slip never
/// steers friction by its rounding), and far below the results' accuracy (1e-7 V at the
/// default tolerance).
const ZERO_SLIP_PER_TOLERANCE: f64 = 100.0;
/// Safety net: widest zero band (fraction of V) that a crawling or dithering integration may
/// escalate to. Not reached in any test; it bounds the cost of an unforeseen stiff case.
const WIDEST_ZERO: f64 = 1e-5;
/// Steps after which a phase counts as crawling.
const CRAWL_STEPS: usize = 5000;
/// Phases after which an impact counts as dithering: the zero band widens at every such count.
const DITHER_PHASES: usize = 20;
/// A creeping slip growing faster than this (fraction of V per unit impulse M V) is robust:
/// its direction can be frozen while it grows out of the zero band.
const ROBUST_CREEP: f64 = 1e-1;
/// A slip growing out of zero is followed as a slip once it exceeds this many zero bands.
/// Until then its direction is the quasi-static creep's, which lags a slow creep's own: at 100
/// the worst of 200,000 random cushion impacts was off by 2e-6, at 10 by 5.5e-7; lower only
/// costs steps (docs/impact-convergence.md).
const ESTABLISHED_PER_ZERO: f64 = 10.0;
/// Vertical speed (fraction of V) below which a ball at a support event has landed.
const LANDED: f64 = 1e-12;

/// The velocities' tolerance per step, in units of the slip tolerance `tol` (see
/// [`SlipAware`]). Chosen on convergence sweeps (docs/impact-convergence.md): at 30 the worst
/// of 200,000 random cushion impacts is 5.5e-7 of V from the converged result (at 100, 9.6e-7).
const VELOCITY_PER_SLIP_TOLERANCE: f64 = 30.0;

/// The impacts' measure of a step's error. Velocities and spins are held to a tolerance
/// (absolute and relative) `VELOCITY_PER_SLIP_TOLERANCE` times `tol`. What friction reads
/// from a slip, though, is its direction, whose error is the slip's error over its size: each
/// slip is held to `tol (1 + VELOCITY_PER_SLIP_TOLERANCE |slip|)`, so that a large slip is
/// followed as loosely as the velocities and one near zero, where a stick, a release or a
/// reversal is decided, to `tol` itself.
struct SlipAware<S> {
    tol: f64,
    /// Velocities' tolerance over `tol`.
    loose: f64,
    /// Components the velocities' mean is taken over (those of the whole state).
    dim: usize,
    /// The three slips (primary, cloth under each body) of a state or of an error.
    slips: S,
}

impl<const M: usize, S: Fn(&[f64; M]) -> [Vec3; 3]> ErrorMeasure<M> for SlipAware<S> {
    fn measure(&self, y0: &[f64; M], y1: &[f64; M], err: &[f64; M]) -> f64 {
        let loose = self.loose * self.tol;
        let mut sum = dopri::mixed_sum(y0, y1, err, loose);
        let (slip, slip_err) = ((self.slips)(y1), (self.slips)(err));
        for k in 0..3 {
            let r = slip_err[k].norm() / (self.tol + loose * slip[k].norm());
            sum += r * r;
        }
        (sum / (self.dim + 3) as f64).sqrt()
    }
}

const N: usize = 13;
/// Events: end of compression, end of restitution, one per frictional contact (the primary
/// one and the cloth under each body), one per body's support.
const K: usize = 7;

/// How a frictional contact behaves during a phase.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Friction {
    /// No friction (zero coefficient, or no normal force).
    Off,
    /// Slipping: friction mu N against the slip; the slip's direction when the phase began.
    Slip(Vec3),
    /// At zero slip: holding, or creeping out of zero, as Coulomb's law decides at every
    /// instant ([`Contact::at_zero`]).
    AtZero,
    /// Creeping robustly out of zero: friction mu N against this (consistent) direction until
    /// the slip is established; the direction cannot change in that instant.
    Starting(Vec3),
}

#[derive(Clone, Copy, Debug)]
struct Mode {
    /// The primary contact, then the cloth under body 0 and body 1.
    friction: [Friction; 3],
    compressing: bool,
    w_target: f64,
    /// Slip (fraction of V) below which a slip counts as zero.
    zero: f64,
}

/// Which of the faster ways through an impact are taken: `flat`, the flattened slopes and the
/// reduced state of a fixed body (bitwise the same results as the general ones); `establish`,
/// Heun's step for a slip growing out of zero (`impulse/establish.rs`; the same results to
/// the tolerance). The tests compare each with the general path.
#[derive(Clone, Copy, Debug)]
struct Paths {
    flat: bool,
    establish: bool,
}

impl Paths {
    const FAST: Paths = Paths {
        flat: true,
        establish: true,
    };
}

/// One phase to integrate: its mode, start, first step, and whether a starting slip may be
/// established by Heun's step.
struct Run<'a> {
    mode: &'a Mode,
    p: f64,
    h: f64,
    establish: bool,
}

impl Run<'_> {
    /// The phase from state `y` (the whole state or a reduced one) with slopes `f`, events
    /// `g`, slips `slips` and step error `measure`.
    fn go<const M: usize, F, G, S, X>(
        &self,
        y: [f64; M],
        f: &F,
        g: &G,
        slips: &S,
        measure: &X,
        mut on_step: impl FnMut(f64, &[f64; M]),
    ) -> dopri::Phase<M>
    where
        F: Fn(&[f64; M]) -> [f64; M],
        G: Events<M, K>,
        S: Fn(&[f64; M]) -> [Vec3; 3],
        X: ErrorMeasure<M>,
    {
        let shortcut = if self.establish {
            establish::establish(self.mode, &y, f, g, slips, measure)
        } else {
            None
        };
        if let Some((dp, y1, ev)) = shortcut {
            on_step(self.p + dp, &y1);
            return dopri::Phase {
                x: self.p + dp,
                y: y1,
                stop: Stop::Event(ev),
                h: self.h,
                steps: 1,
            };
        }
        dopri::integrate(
            f,
            g,
            self.p,
            y,
            self.h,
            measure,
            ROOT_TOLERANCE,
            CRAWL_STEPS,
            on_step,
        )
    }
}

/// All forces per unit dP, besides the primary normal impulse.
#[derive(Clone, Copy, Debug)]
struct Forces {
    /// Friction on body 0 at the primary contact (body 1 gets the opposite).
    primary: Vec3,
    /// Cloth friction on each body.
    cloth: [Vec3; 2],
    /// Cloth reaction on each body.
    reaction: [f64; 2],
}

fn v3(y: &[f64; N], i: usize) -> Vec3 {
    Vec3::new(y[i], y[i + 1], y[i + 2])
}

fn put(y: &mut [f64; N], i: usize, v: Vec3) {
    y[i] = v.x;
    y[i + 1] = v.y;
    y[i + 2] = v.z;
}

fn unit_or(v: Vec3, fallback: Vec3) -> Vec3 {
    let n = v.norm();
    if n > 0.0 { v / n } else { fallback }
}

/// Direction of a slip: its own while it is measurably non-zero (above `zero`), otherwise
/// `chosen` (the direction the phase began with), so that noise in a nil slip never steers
/// friction.
fn slip_direction(s: Vec3, chosen: Vec3, zero: f64) -> Vec3 {
    let n = s.norm();
    // One division and three products rather than three divisions: the slopes are a chain of
    // dependent evaluations, and a division is slow.
    if n > zero { s * (1.0 / n) } else { chosen }
}

/// The event function of a frictional contact under `law` whose slip is `s`: it changes sign
/// when the slip turns through 90 degrees from the phase's direction, and drops to exactly zero
/// when the slip comes down to zero (a slip growing out of zero arms it without a sign change);
/// a slip creeping out of zero crosses zero when it is established.
fn slip_event(law: Friction, s: Vec3, zero: f64) -> f64 {
    match law {
        Friction::Off => 0.0,
        Friction::Slip(r) => {
            if s.norm() > 2.0 * zero {
                s.dot(&r)
            } else {
                0.0
            }
        }
        Friction::AtZero | Friction::Starting(_) => s.norm() - ESTABLISHED_PER_ZERO * zero,
    }
}

/// Offsets of each body's velocity and spin in the state vector.
const VEL: [usize; 2] = [0, 6];
const SPIN: [usize; 2] = [3, 9];
const WORK: usize = 12;
/// The entries that change when body 1 is fixed: body 0's velocity and spin, and the work.
const FREE: [usize; 7] = [0, 1, 2, 3, 4, 5, WORK];

/// Solves the small dense system `a x = b` (n <= 6) by Gaussian elimination with partial
/// pivoting; `None` if it is singular.
fn solve_dense(a: &mut [[f64; 6]; 6], b: &mut [f64; 6], n: usize) -> Option<()> {
    for c in 0..n {
        let p = (c..n).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))?;
        if a[p][c].abs() < 1e-14 {
            return None;
        }
        a.swap(c, p);
        b.swap(c, p);
        for r in c + 1..n {
            let f = a[r][c] / a[c][c];
            for k in c..n {
                a[r][k] -= f * a[c][k];
            }
            b[r] -= f * b[c];
        }
    }
    for c in (0..n).rev() {
        let s: f64 = (c + 1..n).map(|k| a[c][k] * b[k]).sum();
        b[c] = (b[c] - s) / a[c][c];
    }
    Some(())
}

/// A contact's slip rate (in its tangent basis) as an affine function of its friction F:
/// `at_zero + per_unit F`.
#[derive(Clone, Copy, Debug)]
struct Affine {
    at_zero: [f64; 2],
    per_unit: [[f64; 2]; 2],
}

/// Velocities at the contacts in one state, computed once per evaluation.
#[derive(Clone, Copy, Debug)]
struct Local {
    /// Normal relative velocity at the primary contact (positive approaching).
    vn: f64,
    /// Slips of the three frictional contacts (primary, cloth under body 0, body 1).
    slip: [Vec3; 3],
}

/// The bodies' velocities and spins in one state (or their rates).
#[derive(Clone, Copy, Debug)]
struct Bodies {
    vel: [Vec3; 2],
    spin: [Vec3; 2],
}

impl Bodies {
    /// Those of the whole state `y`.
    fn of(y: &[f64; N]) -> Bodies {
        Bodies {
            vel: VEL.map(|i| v3(y, i)),
            spin: SPIN.map(|i| v3(y, i)),
        }
    }

    /// Those of a reduced state `z` (the entries [`FREE`]), body 1 fixed at rest.
    fn of_free(z: &[f64; FREE.len()]) -> Bodies {
        Bodies {
            vel: [Vec3::new(z[0], z[1], z[2]), Vec3::zeros()],
            spin: [Vec3::new(z[3], z[4], z[5]), Vec3::zeros()],
        }
    }

    /// The whole state with these velocities and spins and the work `work`.
    fn state(&self, work: f64) -> [f64; N] {
        let mut y = [0.0; N];
        for i in 0..2 {
            put(&mut y, VEL[i], self.vel[i]);
            put(&mut y, SPIN[i], self.spin[i]);
        }
        y[WORK] = work;
        y
    }

    /// Slip of body `i`'s cloth contact point, as [`Contact::cloth_velocity`].
    fn cloth_slip(&self, i: usize) -> Vec3 {
        let (v, w) = (self.vel[i], self.spin[i]);
        Vec3::new(v.x - w.y, v.y + w.x, 0.0)
    }
}

impl Contact {
    /// Velocity of body 0's contact point relative to body 1's.
    fn primary_velocity(&self, y: &[f64; N]) -> Vec3 {
        let p = |i: usize| v3(y, VEL[i]) + v3(y, SPIN[i]).cross(&self.arm[i]);
        p(0) - p(1)
    }

    /// Slip of body `i`'s cloth contact point (horizontal): v + w x (-z) in units of R.
    fn cloth_velocity(&self, y: &[f64; N], i: usize) -> Vec3 {
        let (v, w) = (VEL[i], SPIN[i]);
        Vec3::new(y[v] - y[w + 1], y[v + 1] + y[w], 0.0)
    }

    fn local(&self, y: &[f64; N]) -> Local {
        let u = self.primary_velocity(y);
        let vn = u.dot(&self.normal);
        Local {
            vn,
            slip: [
                u - vn * self.normal,
                self.cloth_velocity(y, 0),
                self.cloth_velocity(y, 1),
            ],
        }
    }

    /// Two unit vectors spanning contact `k`'s tangent plane.
    fn tangents(&self, k: usize) -> [Vec3; 2] {
        if k == 0 {
            let t = unit_or(
                self.normal.cross(&Vec3::z()),
                self.normal.cross(&Vec3::x()).normalize(),
            );
            [t, self.normal.cross(&t)]
        } else {
            [Vec3::x(), Vec3::y()]
        }
    }

    fn coefficient(&self, k: usize) -> f64 {
        if k == 0 { self.mu } else { self.mu_cloth }
    }

    /// Vertical component of the non-cloth force on each body (per unit dP).
    fn vertical_forces(&self, fp: Vec3) -> [f64; 2] {
        [fp.z - self.normal.z, self.normal.z - fp.z]
    }

    /// The cloth's reaction on body `i` (per unit dP) when the other vertical forces on it
    /// are `fz`: it holds a ball that is down on the cloth against forces pushing it down, and
    /// lets it rise freely.
    fn reaction(&self, y: &[f64; N], i: usize, fz: f64) -> f64 {
        if self.bodies[i].on_cloth && y[VEL[i] + 2] <= 0.0 {
            (-fz).max(0.0)
        } else {
            0.0
        }
    }

    /// Forces with the holding frictions of sticking contacts given by `held`.
    fn forces_with(&self, y: &[f64; N], loc: &Local, mode: &Mode, held: &[Vec3; 3]) -> Forces {
        let primary = match mode.friction[0] {
            Friction::Off => Vec3::zeros(),
            Friction::Slip(r) => -self.mu * slip_direction(loc.slip[0], r, mode.zero),
            Friction::Starting(r) => -self.mu * r,
            Friction::AtZero => held[0],
        };
        let fz = self.vertical_forces(primary);
        let reaction = [self.reaction(y, 0, fz[0]), self.reaction(y, 1, fz[1])];
        let cloth = [0, 1].map(|i| match mode.friction[1 + i] {
            Friction::Off => Vec3::zeros(),
            Friction::Slip(r) => {
                -self.mu_cloth * reaction[i] * slip_direction(loc.slip[1 + i], r, mode.zero)
            }
            Friction::Starting(r) => -self.mu_cloth * reaction[i] * r,
            Friction::AtZero => held[1 + i],
        });
        Forces {
            primary,
            cloth,
            reaction,
        }
    }

    fn derivatives(&self, loc: &Local, f: &Forces) -> [f64; N] {
        let mut dy = [0.0; N];
        let torque_p = [self.arm[0].cross(&f.primary), f.primary.cross(&self.arm[1])];
        let sign = [1.0, -1.0];
        for i in 0..2 {
            let b = &self.bodies[i];
            if b.inv_mass == 0.0 && b.inv_inertia == 0.0 {
                continue;
            }
            let c = f.cloth[i];
            let mut force = sign[i] * (f.primary - self.normal) + c;
            force.z += f.reaction[i];
            // The cloth's friction acts at the lowest point: (-z) x c = (c_y, -c_x, 0).
            let torque = torque_p[i] + Vec3::new(c.y, -c.x, 0.0);
            put(&mut dy, VEL[i], b.inv_mass * force);
            put(&mut dy, SPIN[i], b.inv_inertia * torque);
        }
        dy[WORK] = loc.vn;
        dy
    }

    /// [`Contact::rhs`] for a mode with no contact at zero slip (every step of most phases),
    /// flattened: the same operations in the same order (so bitwise the same result), without
    /// the general path's intermediate structures, and skipping what a fixed body or a contact
    /// without friction does not need. Returns the bodies' rates and the work's.
    #[inline(always)]
    fn rhs_slipping(&self, b: &Bodies, mode: &Mode) -> (Bodies, f64) {
        let moving = self.moving();
        let (u, vn) = self.primary_motion(b, moving);
        let n = self.normal;
        let primary = match mode.friction[0] {
            Friction::Slip(r) => -self.mu * slip_direction(u - vn * n, r, mode.zero),
            Friction::Starting(r) => -self.mu * r,
            _ => Vec3::zeros(),
        };
        let fz = self.vertical_forces(primary);
        let torque_p = [self.arm[0].cross(&primary), primary.cross(&self.arm[1])];
        let sign = [1.0, -1.0];
        let mut d = Bodies {
            vel: [Vec3::zeros(); 2],
            spin: [Vec3::zeros(); 2],
        };
        for i in 0..2 {
            if !moving[i] {
                continue;
            }
            let reaction = if self.bodies[i].on_cloth && b.vel[i].z <= 0.0 {
                (-fz[i]).max(0.0)
            } else {
                0.0
            };
            let c = match mode.friction[1 + i] {
                Friction::Slip(r) => {
                    -self.mu_cloth * reaction * slip_direction(b.cloth_slip(i), r, mode.zero)
                }
                Friction::Starting(r) => -self.mu_cloth * reaction * r,
                _ => Vec3::zeros(),
            };
            let mut force = sign[i] * (primary - n) + c;
            force.z += reaction;
            let torque = torque_p[i] + Vec3::new(c.y, -c.x, 0.0);
            d.vel[i] = self.bodies[i].inv_mass * force;
            d.spin[i] = self.bodies[i].inv_inertia * torque;
        }
        (d, vn)
    }

    /// Velocity of body 0's contact point relative to body 1's, and its normal part, as
    /// [`Contact::local`] forms them (a fixed body's contact point is at rest: +0, whose
    /// subtraction changes nothing).
    fn primary_motion(&self, b: &Bodies, moving: [bool; 2]) -> (Vec3, f64) {
        let mut u = b.vel[0] + b.spin[0].cross(&self.arm[0]);
        if moving[1] {
            u -= b.vel[1] + b.spin[1].cross(&self.arm[1]);
        }
        (u, u.dot(&self.normal))
    }

    /// [`Contact::events`] for a mode whose primary contact is not at zero slip, flattened as
    /// [`Contact::rhs_slipping`] (bitwise the same values).
    #[inline(always)]
    fn events_slipping(&self, b: &Bodies, work: f64, mode: &Mode) -> [f64; K] {
        let moving = self.moving();
        let (u, vn) = self.primary_motion(b, moving);
        let mut g = [0.0; K];
        if mode.compressing {
            g[0] = vn;
        } else {
            g[1] = work - mode.w_target;
        }
        for k in 0..3 {
            if mode.friction[k] == Friction::Off {
                continue;
            }
            let s = if k == 0 {
                u - vn * self.normal
            } else {
                b.cloth_slip(k - 1)
            };
            g[2 + k] = slip_event(mode.friction[k], s, mode.zero);
        }
        let primary = match mode.friction[0] {
            Friction::Slip(r) => -self.mu * slip_direction(u - vn * self.normal, r, mode.zero),
            Friction::Starting(r) => -self.mu * r,
            _ => Vec3::zeros(),
        };
        let fz = self.vertical_forces(primary);
        for i in 0..2 {
            if self.bodies[i].on_cloth {
                let vz = b.vel[i].z;
                g[5 + i] = if vz > 0.0 { vz } else { fz[i] };
            }
        }
        g
    }

    /// Which bodies move (a fixed body's velocities stay zero).
    fn moving(&self) -> [bool; 2] {
        self.bodies
            .map(|b| !(b.inv_mass == 0.0 && b.inv_inertia == 0.0))
    }

    /// Rate of change of contact `k`'s slip, given the state's rates `dy`.
    fn slip_rate(&self, dy: &[f64; N], k: usize) -> Vec3 {
        if k == 0 {
            let dp = |i: usize| v3(dy, VEL[i]) + v3(dy, SPIN[i]).cross(&self.arm[i]);
            let du = dp(0) - dp(1);
            du - du.dot(&self.normal) * self.normal
        } else {
            self.cloth_velocity(dy, k - 1)
        }
    }

    /// Slip rates (in each contact's tangent basis) of the contacts in `which`, when the
    /// contacts at zero slip exert the frictions `held`.
    fn rates(
        &self,
        y: &[f64; N],
        loc: &Local,
        mode: &Mode,
        held: &[Vec3; 3],
        which: &[usize],
    ) -> [f64; 6] {
        let dy = self.derivatives(loc, &self.forces_with(y, loc, mode, held));
        let mut r = [0.0; 6];
        for (j, &k) in which.iter().enumerate() {
            let d = self.slip_rate(&dy, k);
            let t = self.tangents(k);
            r[2 * j] = d.dot(&t[0]);
            r[2 * j + 1] = d.dot(&t[1]);
        }
        r
    }

    /// Sets in `held` the frictions that keep the slip rates of the contacts in `which` at
    /// zero, the other frictions in `held` fixed. The rates are affine in these frictions, so
    /// this is one small linear solve. For a single contact, also returns its rates at zero
    /// friction and their change per unit friction along each tangent (what
    /// [`Contact::creep`] needs, so that it need not probe them again).
    fn hold(
        &self,
        y: &[f64; N],
        loc: &Local,
        mode: &Mode,
        held: &mut [Vec3; 3],
        which: &[usize],
    ) -> Option<Affine> {
        let n = 2 * which.len();
        for &k in which {
            held[k] = Vec3::zeros();
        }
        let base = self.rates(y, loc, mode, held, which);
        let mut a = [[0.0; 6]; 6];
        for col in 0..n {
            let (j, c) = (col / 2, col % 2);
            let mut probe = *held;
            probe[which[j]] = self.tangents(which[j])[c];
            let r = self.rates(y, loc, mode, &probe, which);
            for row in 0..n {
                a[row][col] = r[row] - base[row];
            }
        }
        let single = (n == 2).then(|| Affine {
            at_zero: [base[0], base[1]],
            per_unit: [[a[0][0], a[0][1]], [a[1][0], a[1][1]]],
        });
        let mut b = [0.0; 6];
        for row in 0..n {
            b[row] = -base[row];
        }
        if solve_dense(&mut a, &mut b, n).is_some() {
            for (j, &k) in which.iter().enumerate() {
                let t = self.tangents(k);
                held[k] = b[2 * j] * t[0] + b[2 * j + 1] * t[1];
            }
        }
        single
    }

    /// How contact `k`, at zero slip and unable to hold, creeps out of zero (the other
    /// frictions in `held` fixed). Its slip rate is affine in its friction F: rate = d + B F.
    /// With Coulomb friction F = -c s (c = mu N) a slip growing as lambda s needs
    /// (lambda I + c B) s = d with |s| = 1 and lambda >= 0; |(lambda I + c B)^-1 d| falls with
    /// lambda, so lambda is found in a bracket (by Newton's method, safeguarded by bisection;
    /// lambda = 0, the edge of holding, gives the direction opposite to the holding force, so
    /// friction is continuous there). Returns the friction, the direction and lambda.
    fn creep(
        &self,
        y: &[f64; N],
        loc: &Local,
        mode: &Mode,
        held: &[Vec3; 3],
        k: usize,
        known: Option<Affine>,
    ) -> (Vec3, Vec3, f64) {
        let t = self.tangents(k);
        let mut probe = *held;
        probe[k] = Vec3::zeros();
        let cap =
            self.coefficient(k) * self.normal_force(&self.forces_with(y, loc, mode, &probe), k);
        let Affine {
            at_zero: d,
            per_unit: b,
        } = known.unwrap_or_else(|| {
            let d6 = self.rates(y, loc, mode, &probe, &[k]);
            let d = [d6[0], d6[1]];
            let mut b = [[0.0; 2]; 2];
            for c in 0..2 {
                probe[k] = t[c];
                let r = self.rates(y, loc, mode, &probe, &[k]);
                b[0][c] = r[0] - d[0];
                b[1][c] = r[1] - d[1];
            }
            Affine {
                at_zero: d,
                per_unit: b,
            }
        });
        // s(lambda) = M^-1 d with M = lambda I + c B, and M^-1 s (for d s / d lambda = -M^-1 s).
        let s_of = |lambda: f64| {
            let (a, bb, c, dd) = (
                lambda + cap * b[0][0],
                cap * b[0][1],
                cap * b[1][0],
                lambda + cap * b[1][1],
            );
            let det = a * dd - bb * c;
            let s = [(dd * d[0] - bb * d[1]) / det, (a * d[1] - c * d[0]) / det];
            let ms = [(dd * s[0] - bb * s[1]) / det, (a * s[1] - c * s[0]) / det];
            (s, ms)
        };
        let norm = |v: [f64; 2]| (v[0] * v[0] + v[1] * v[1]).sqrt();
        let mut lambda = 0.0;
        if norm(s_of(0.0).0) > 1.0 {
            // Newton's method on 1/|s| - 1, nearly linear in lambda (|s| ~ |d| / lambda for
            // large lambda), so a handful of steps reach rounding; kept strictly inside the
            // bracket [lo, hi] of the root, halving it whenever a step would not be, and
            // stopping at the width a bisection of the whole bracket would end at.
            let (mut lo, mut hi) = (0.0, norm(d) + cap * (b[0][0].abs() + b[1][1].abs()) + 1.0);
            let width = hi * f64::EPSILON;
            for _ in 0..100 {
                let (s, ms) = s_of(lambda);
                let ns = norm(s);
                let g = 1.0 / ns - 1.0;
                if g == 0.0 {
                    break;
                } else if g < 0.0 {
                    lo = lambda;
                } else {
                    hi = lambda;
                }
                let slope = (s[0] * ms[0] + s[1] * ms[1]) / (ns * ns * ns);
                let mut next = lambda - g / slope;
                if !(next > lo && next < hi) {
                    next = 0.5 * (lo + hi);
                }
                let done = (next - lambda).abs() <= 1e-15 * next || hi - lo <= width;
                lambda = next;
                if done {
                    break;
                }
            }
        }
        let s = s_of(lambda).0;
        let dir = unit_or(s[0] * t[0] + s[1] * t[1], t[0]);
        (-cap * dir, dir, lambda)
    }

    /// Frictions of the contacts at zero slip, by Coulomb's law taken jointly: those that can
    /// hold do (one linear solve for all of them), the others creep at mu N (one at a time,
    /// each release changing what the rest need). Also returns, per contact, the creeping
    /// direction and its lambda.
    fn at_zero(
        &self,
        y: &[f64; N],
        loc: &Local,
        mode: &Mode,
    ) -> ([Vec3; 3], [Option<(Vec3, f64)>; 3]) {
        let mut held = [Vec3::zeros(); 3];
        let mut creeping: [Option<(Vec3, f64)>; 3] = [None; 3];
        for _ in 0..3 {
            let mut which_at = [0usize; 3];
            let mut n = 0;
            for k in 0..3 {
                if mode.friction[k] == Friction::AtZero && creeping[k].is_none() {
                    which_at[n] = k;
                    n += 1;
                }
            }
            if n == 0 {
                break;
            }
            // Alone at zero, the contact's rates as `hold` probed them are those `creep` needs
            // (the other frictions are the same).
            let single = self.hold(y, loc, mode, &mut held, &which_at[..n]);
            let f = self.forces_with(y, loc, mode, &held);
            let excess = |k: usize| held[k].norm() - self.coefficient(k) * self.normal_force(&f, k);
            let worst = which_at[..n]
                .iter()
                .copied()
                .filter(|&k| excess(k) > 0.0)
                .max_by(|&a, &b| excess(a).total_cmp(&excess(b)));
            let Some(k) = worst else { break };
            let (force, dir, lambda) = self.creep(y, loc, mode, &held, k, single);
            held[k] = force;
            creeping[k] = Some((dir, lambda));
        }
        (held, creeping)
    }

    /// All forces under `mode` (contacts at zero slip by [`Contact::at_zero`]).
    fn forces(&self, y: &[f64; N], loc: &Local, mode: &Mode) -> Forces {
        if !mode.friction.contains(&Friction::AtZero) {
            return self.forces_with(y, loc, mode, &[Vec3::zeros(); 3]);
        }
        let (held, _) = self.at_zero(y, loc, mode);
        self.forces_with(y, loc, mode, &held)
    }

    /// Normal force (per unit dP) at contact `k`.
    fn normal_force(&self, f: &Forces, k: usize) -> f64 {
        if k == 0 { 1.0 } else { f.reaction[k - 1] }
    }

    /// The slopes under `mode`; `flat` allows [`Contact::rhs_slipping`] where it applies.
    fn rhs(&self, y: &[f64; N], mode: &Mode, flat: bool) -> [f64; N] {
        if flat && !mode.friction.contains(&Friction::AtZero) {
            let (d, vn) = self.rhs_slipping(&Bodies::of(y), mode);
            return d.state(vn);
        }
        let loc = self.local(y);
        self.derivatives(&loc, &self.forces(y, &loc, mode))
    }

    /// The event functions at `y`. Forces are computed only as far as the events need them:
    /// none for compression, restitution and slips; the primary friction for the supports.
    fn events(&self, y: &[f64; N], mode: &Mode) -> [f64; K] {
        let loc = self.local(y);
        let mut g = [0.0; K];
        if mode.compressing {
            g[0] = loc.vn;
        } else {
            g[1] = y[WORK] - mode.w_target;
        }
        for k in 0..3 {
            g[2 + k] = slip_event(mode.friction[k], loc.slip[k], mode.zero);
        }
        let primary = if mode.friction[0] == Friction::AtZero {
            self.forces(y, &loc, mode).primary
        } else {
            self.forces_with(y, &loc, mode, &[Vec3::zeros(); 3]).primary
        };
        let fz = self.vertical_forces(primary);
        for i in 0..2 {
            if self.bodies[i].on_cloth {
                // Where the cloth starts or stops holding the ball: the vertical force changes
                // sign (ball down) or the ball comes back down (ball up).
                let vz = y[VEL[i] + 2];
                g[5 + i] = if vz > 0.0 { vz } else { fz[i] };
            }
        }
        g
    }

    /// The mode at state `y`: a contact slips if its slip is measurable, otherwise it is at
    /// zero (holding or creeping, decided continuously), or has no friction at all.
    fn mode_at(&self, y: &[f64; N], compressing: bool, w_target: f64, zero: f64) -> Mode {
        let loc = self.local(y);
        let mut mode = Mode {
            friction: [Friction::Off; 3],
            compressing,
            w_target,
            zero,
        };
        for k in 0..3 {
            let on_cloth = k == 0 || self.bodies[k - 1].on_cloth;
            if self.coefficient(k) <= 0.0 || !on_cloth {
                continue;
            }
            let s = loc.slip[k];
            mode.friction[k] = if s.norm() > 2.0 * zero {
                Friction::Slip(s.normalize())
            } else {
                Friction::AtZero
            };
        }
        // A cloth contact under a ball that is not pressed down has no friction at all. The
        // reactions depend on the primary friction alone, so the contacts at zero slip need
        // solving here only when the primary contact is one of them.
        let f = if mode.friction[0] == Friction::AtZero {
            self.forces(y, &loc, &mode)
        } else {
            self.forces_with(y, &loc, &mode, &[Vec3::zeros(); 3])
        };
        for i in 0..2 {
            if f.reaction[i] <= 0.0 {
                mode.friction[1 + i] = Friction::Off;
            }
        }
        // A contact creeping out of zero fast (its slip growing at more than ROBUST_CREEP per
        // unit impulse) keeps its direction until established.
        let (_, creeping) = self.at_zero(y, &loc, &mode);
        for k in 0..3 {
            if let Some((dir, _)) = creeping[k].filter(|c| c.1 > ROBUST_CREEP) {
                mode.friction[k] = Friction::Starting(dir);
            }
        }
        mode
    }

    /// The error measure of a step of the whole state.
    fn measure(&self, tol: f64) -> SlipAware<impl Fn(&[f64; N]) -> [Vec3; 3] + '_> {
        self.measure_with(tol, |y: &[f64; N]| self.local(y).slip)
    }

    /// The error measure of a step of a state (the whole or a reduced one) whose slips are
    /// `slips`; its mean is over the whole state's components.
    fn measure_with<S>(&self, tol: f64, slips: S) -> SlipAware<S> {
        SlipAware {
            tol,
            loose: VELOCITY_PER_SLIP_TOLERANCE,
            dim: N,
            slips,
        }
    }

    /// Integrates one phase under `mode` from impulse `p`, state `y`, first step `h`, until an
    /// event (or a crawl); `on_step` sees every accepted point. `paths` says which faster
    /// paths may be taken.
    #[allow(clippy::too_many_arguments)]
    fn integrate_phase(
        &self,
        mode: &Mode,
        p: f64,
        y: [f64; N],
        h: f64,
        tol: f64,
        paths: Paths,
        mut on_step: impl FnMut(f64, &[f64; N]),
    ) -> dopri::Phase<N> {
        let flat = paths.flat;
        let flat_events = flat && mode.friction[0] != Friction::AtZero;
        let f = |y: &[f64; N]| self.rhs(y, mode, flat);
        let g = |y: &[f64; N]| {
            if flat_events {
                self.events_slipping(&Bodies::of(y), y[WORK], mode)
            } else {
                self.events(y, mode)
            }
        };
        let run = Run {
            mode,
            p,
            h,
            establish: paths.establish,
        };
        let at_rest = (6..WORK).all(|i| y[i] == 0.0);
        if !flat || self.moving()[1] || !at_rest {
            let measure = self.measure(tol);
            let slips = |y: &[f64; N]| self.local(y).slip;
            return run.go(y, &f, &g, &slips, &measure, on_step);
        }
        // A fixed body 1 (at rest, as a cushion) keeps its velocities (zero): only the other
        // entries are integrated, nearly halving the integrator's work, with the steps and
        // results of the whole state (the error measure's mean is over the whole state).
        let full = |z: &[f64; FREE.len()]| {
            let mut w = [0.0; N];
            for (j, &i) in FREE.iter().enumerate() {
                w[i] = z[j];
            }
            w
        };
        let part = |w: &[f64; N]| FREE.map(|i| w[i]);
        let on_step = |x: f64, z: &[f64; FREE.len()]| on_step(x, &full(z));
        let ph = if let Some(laws) = AgainstFixed::new(self, mode) {
            let slips = |z: &[f64; FREE.len()]| laws.slips(z);
            let measure = self.measure_with(tol, slips);
            run.go(
                part(&y),
                &|z| laws.slopes(z),
                &laws,
                &slips,
                &measure,
                on_step,
            )
        } else {
            let work = FREE.len() - 1;
            let slips = |z: &[f64; FREE.len()]| self.local(&full(z)).slip;
            let measure = self.measure_with(tol, slips);
            let g = |z: &[f64; FREE.len()]| {
                if flat_events {
                    self.events_slipping(&Bodies::of_free(z), z[work], mode)
                } else {
                    g(&full(z))
                }
            };
            run.go(
                part(&y),
                &|z| part(&f(&full(z))),
                &g,
                &slips,
                &measure,
                on_step,
            )
        };
        dopri::Phase {
            x: ph.x,
            y: full(&ph.y),
            stop: ph.stop,
            h: ph.h,
            steps: ph.steps,
        }
    }

    /// Resolves the impact of bodies with velocities `k` (dimensional), radius `radius` and
    /// reference mass `mass`, to the default [`TOLERANCE`]; `trace` receives samples of its
    /// progress if given.
    pub fn solve(
        &self,
        k: &Kinematics,
        radius: f64,
        mass: f64,
        trace: Option<&mut Vec<Sample>>,
    ) -> Result<Outcome, ImpactError> {
        self.solve_to(k, radius, mass, TOLERANCE, trace)
    }

    /// The thesis's own scheme, for comparison (thesis §6.1.4.2, §6.2.4): forward Euler in P
    /// with `steps` equal increments of the frictionless impulse, friction against the slip of
    /// the step's start, compression and restitution work by the trapezoidal rule (eq. 6.16).
    /// First order: its error falls as 1/steps.
    pub fn euler(
        &self,
        k: &Kinematics,
        radius: f64,
        steps: usize,
    ) -> Result<Kinematics, ImpactError> {
        let (mut y, v_scale) = self.scaled(k, radius)?;
        let inv_sum: f64 = self.bodies.iter().map(|b| b.inv_mass).sum();
        let dp = (1.0 + self.e) / inv_sum.max(1e-12) / steps as f64;
        let (mut compressing, mut target) = (true, 0.0);
        for _ in 0..100 * steps {
            let mut mode = Mode {
                friction: [Friction::Off; 3],
                compressing,
                w_target: target,
                zero: 0.0,
            };
            let loc = self.local(&y);
            for kk in 0..3 {
                let s = loc.slip[kk];
                if self.coefficient(kk) > 0.0 && s.norm() > 0.0 {
                    mode.friction[kk] = Friction::Slip(s.normalize());
                }
            }
            let vn0 = loc.vn;
            let dy = self.derivatives(
                &loc,
                &self.forces_with(&y, &loc, &mode, &[Vec3::zeros(); 3]),
            );
            for (v, d) in y.iter_mut().zip(dy) {
                *v += dp * d;
            }
            let vn1 = self.primary_velocity(&y).dot(&self.normal);
            y[WORK] += dp * (0.5 * (vn0 + vn1) - vn0);
            if compressing && vn1 <= 0.0 {
                compressing = false;
                target = (1.0 - self.e * self.e) * y[WORK];
            }
            if !compressing && y[WORK] <= target {
                return Ok(Kinematics {
                    vel: [0, 1].map(|i| v3(&y, VEL[i]) * v_scale),
                    spin: [0, 1].map(|i| v3(&y, SPIN[i]) * v_scale / radius),
                });
            }
        }
        Err(ImpactError("the Euler scheme did not finish".into()))
    }

    /// The state vector in scaled units, and the velocity scale (the approach speed).
    fn scaled(&self, k: &Kinematics, radius: f64) -> Result<([f64; N], f64), ImpactError> {
        let u0 = (k.vel[0] + k.spin[0].cross(&(radius * self.arm[0])))
            - (k.vel[1] + k.spin[1].cross(&(radius * self.arm[1])));
        let approach = u0.dot(&self.normal);
        if !(approach > 0.0 && approach.is_finite()) {
            return Err(ImpactError(format!(
                "the bodies are not approaching (normal speed {approach} m/s)"
            )));
        }
        let mut y = [0.0; N];
        for i in 0..2 {
            put(&mut y, VEL[i], k.vel[i] / approach);
            put(&mut y, SPIN[i], k.spin[i] * radius / approach);
        }
        Ok((y, approach))
    }

    /// [`Contact::solve`] to a given tolerance `tol` (scaled units, as [`TOLERANCE`]: the
    /// slips' near zero, the velocities' `VELOCITY_PER_SLIP_TOLERANCE` times larger; the zero
    /// band scales with it).
    pub fn solve_to(
        &self,
        k: &Kinematics,
        radius: f64,
        mass: f64,
        tol: f64,
        trace: Option<&mut Vec<Sample>>,
    ) -> Result<Outcome, ImpactError> {
        self.solve_with(k, radius, mass, tol, trace, Paths::FAST)
    }

    /// [`Contact::solve_to`], taking the faster `paths` given.
    fn solve_with(
        &self,
        k: &Kinematics,
        radius: f64,
        mass: f64,
        tol: f64,
        mut trace: Option<&mut Vec<Sample>>,
        paths: Paths,
    ) -> Result<Outcome, ImpactError> {
        if !(0.0..).contains(&self.e) || !self.e.is_finite() {
            return Err(ImpactError(format!("restitution {} out of range", self.e)));
        }
        // Scaled units: velocities / V, spins * R / V, impulse / (M V), work / (M V^2).
        let (mut y, v_scale) = self.scaled(k, radius)?;
        let record = |trace: &mut Option<&mut Vec<Sample>>, p: f64, y: &[f64; N], mode: &Mode| {
            if let Some(t) = trace.as_deref_mut() {
                let loc = self.local(y);
                let reaction = self.forces(y, &loc, mode).reaction;
                t.push(Sample {
                    impulse: p * mass * v_scale,
                    slip: loc.slip[0] * v_scale,
                    cloth_slip: [0, 1].map(|i| {
                        if self.bodies[i].on_cloth {
                            self.cloth_velocity(y, i) * v_scale
                        } else {
                            Vec3::zeros()
                        }
                    }),
                    normal_velocity: loc.vn * v_scale,
                    pressed: reaction.map(|r| r > 0.0),
                });
            }
        };
        if trace.is_some() {
            let first = self.mode_at(&y, true, 0.0, ZERO_SLIP_PER_TOLERANCE * tol);
            record(&mut trace, 0.0, &y, &first);
        }
        let inv_sum: f64 = self.bodies.iter().map(|b| b.inv_mass).sum();
        // About (1 + e) / (1/m0 + 1/m1) in scaled units: the frictionless impulse.
        let p_guess = (1.0 + self.e) / inv_sum.max(1e-12);
        let mut h = p_guess / 8.0;
        let (mut p, mut steps, mut phases) = (0.0, 0, 0);
        let (mut compressing, mut w_target) = (true, 0.0);
        let mut zero = ZERO_SLIP_PER_TOLERANCE * tol;
        let mut p_c = 0.0;
        loop {
            phases += 1;
            if phases > 200 {
                return Err(ImpactError("more than 200 phases".into()));
            }
            if phases % DITHER_PHASES == 0 {
                zero = (10.0 * zero).min(WIDEST_ZERO);
            }
            let mode = self.mode_at(&y, compressing, w_target, zero);
            let ph = self.integrate_phase(&mode, p, y, h, tol, paths, |x, yy| {
                record(&mut trace, x, yy, &mode)
            });
            steps += ph.steps;
            if ph.x > 1e3 * p_guess.max(1.0) {
                return Err(ImpactError("the impulse grew without bound".into()));
            }
            let Stop::Event(ev) = ph.stop else {
                // Crawling: a slip hovers at the edge of sticking (friction capacity and drive
                // in balance), where its direction is stiff at tiny slips. Whether it sticks
                // or creeps changes nothing measurable; widen the zero band and go on.
                if zero >= WIDEST_ZERO || ph.x <= p {
                    return Err(ImpactError("the integration did not converge".into()));
                }
                zero = (10.0 * zero).min(WIDEST_ZERO);
                p = ph.x;
                y = ph.y;
                h = ph.h;
                continue;
            };
            p = ph.x;
            y = ph.y;
            // The next phase starts from the step size reached, but no longer than the whole
            // frictionless impulse (a step across a slow phase grows tenfold, and would be
            // rejected).
            h = ph.h.clamp(1e-9 * p_guess, p_guess);
            match ev {
                0 => {
                    compressing = false;
                    p_c = p;
                    let w_c = y[WORK];
                    w_target = (1.0 - self.e * self.e) * w_c;
                    if self.e == 0.0 {
                        break;
                    }
                }
                1 => break,
                2..=4 => {
                    // A slip turned, stopped or restarted: the next phase's mode says how.
                }
                _ => {
                    // Pressing or lifting changed. A ball coming back down within the impact
                    // (its vertical speed at the root is zero to the root tolerance) lands:
                    // the cloth holds it from here.
                    for i in 0..2 {
                        if self.bodies[i].on_cloth && y[VEL[i] + 2] <= LANDED {
                            y[VEL[i] + 2] = 0.0;
                        }
                    }
                }
            }
        }
        let after = Kinematics {
            vel: [0, 1].map(|i| v3(&y, VEL[i]) * v_scale),
            spin: [0, 1].map(|i| v3(&y, SPIN[i]) * v_scale / radius),
        };
        Ok(Outcome {
            after,
            impulse: p * mass * v_scale,
            compression_impulse: p_c * mass * v_scale,
            steps,
            phases,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::impact::sweep::Rng;

    /// A ball-ball or ball-cushion contact (as the Mathavan models set them up) and random
    /// velocities that approach, with frictions up to 0.6.
    fn random_impact(rng: &mut Rng, cushion: bool) -> (Contact, Kinematics) {
        let (mu, mu_cloth, e) = (
            rng.uniform(0.0, 0.6),
            rng.uniform(0.0, 0.6),
            rng.uniform(0.5, 1.0),
        );
        let angle = rng.uniform(0.0, std::f64::consts::TAU);
        let plan = Vec3::new(angle.cos(), angle.sin(), 0.0);
        // One ball in ten is in the air (off the cloth) at the impact.
        let lifted = rng.uniform(0.0, 1.0) < 0.1;
        let (bodies, normal, arm) = if cushion {
            let n = -(21f64.sqrt() / 5.0) * plan + 0.4 * Vec3::z();
            ([Body::ball(!lifted), Body::fixed()], n, [n, Vec3::zeros()])
        } else {
            ([Body::ball(!lifted), Body::ball(true)], plan, [plan, -plan])
        };
        let c = Contact {
            bodies,
            normal,
            arm,
            mu,
            mu_cloth,
            e,
        };
        let r = 0.02625;
        loop {
            let mut k = Kinematics {
                vel: [rng.vec(3.0), rng.vec(1.0)],
                spin: [rng.vec(3.0 / r), rng.vec(1.0 / r)],
            };
            for i in 0..2 {
                if c.bodies[i].on_cloth {
                    k.vel[i].z = 0.0;
                }
                if c.bodies[i].inv_mass == 0.0 {
                    k.vel[i] = Vec3::zeros();
                    k.spin[i] = Vec3::zeros();
                }
            }
            if c.scaled(&k, r).is_ok() {
                return (c, k);
            }
        }
    }

    #[test]
    fn the_flat_slopes_and_events_are_the_general_ones_bitwise() {
        let mut rng = Rng(0x5eed_1234_abcd_0001);
        for case in 0..20_000 {
            let (c, _) = random_impact(&mut rng, case % 2 == 1);
            let mut y = [0.0; N];
            for (i, v) in y.iter_mut().enumerate() {
                let fixed = (6..12).contains(&i) && c.bodies[1].inv_mass == 0.0;
                *v = if fixed { 0.0 } else { rng.uniform(-2.0, 2.0) };
            }
            for i in 0..2 {
                // Balls down on the cloth (held) or up (free), both.
                if c.bodies[i].on_cloth && rng.uniform(0.0, 1.0) < 0.5 {
                    y[VEL[i] + 2] = 0.0;
                }
            }
            let mut mode = Mode {
                friction: [Friction::Off; 3],
                compressing: true,
                w_target: 0.0,
                zero: 10f64.powf(rng.uniform(-9.0, 0.0)),
            };
            for k in 0..3 {
                let r = rng.vec(1.0).normalize();
                mode.friction[k] = match (rng.uniform(0.0, 4.0)) as usize {
                    0 => Friction::Off,
                    1 => Friction::Slip(r),
                    2 => Friction::Starting(r),
                    _ => Friction::AtZero,
                };
            }
            mode.compressing = rng.uniform(0.0, 1.0) < 0.5;
            let b = Bodies::of(&y);
            if mode.friction[0] != Friction::AtZero {
                let general = c.events(&y, &mode);
                assert_eq!(
                    c.events_slipping(&b, y[WORK], &mode),
                    general,
                    "{c:?} {y:?}"
                );
            }
            if !mode.friction.contains(&Friction::AtZero) {
                let general = c.rhs(&y, &mode, false);
                let (d, vn) = c.rhs_slipping(&b, &mode);
                assert_eq!(d.state(vn), general, "{c:?} {y:?} {mode:?}");
            }
            // A ball against a fixed body, on the reduced state.
            if let Some(laws) = AgainstFixed::new(&c, &mode) {
                let z = FREE.map(|i| y[i]);
                let general = c.rhs(&y, &mode, false);
                assert_eq!(laws.slopes(&z), FREE.map(|i| general[i]), "{c:?} {y:?}");
                assert_eq!(laws.events(&z), c.events(&y, &mode), "{c:?} {y:?}");
                assert_eq!(laws.slips(&z), c.local(&y).slip, "{c:?} {y:?}");
                let all = laws.all(&z);
                for (e, value) in all.into_iter().enumerate() {
                    assert_eq!(laws.one(&z, e).to_bits(), value.to_bits(), "{c:?} {y:?}");
                }
            }
        }
    }

    #[test]
    fn the_fast_paths_give_the_general_integration_bitwise() {
        // The flattened slopes and the reduced state of a fixed cushion change the cost of an
        // impact, not one bit of its result, over random impacts of both kinds (Heun's step
        // for a starting slip taken on either).
        let mut rng = Rng(0x5eed_1234_abcd_0002);
        for case in 0..1_000 {
            let (c, k) = random_impact(&mut rng, case % 2 == 1);
            let flat = Paths::FAST;
            let general = Paths {
                flat: false,
                establish: true,
            };
            let fast = c.solve_with(&k, 0.02625, 0.141, TOLERANCE, None, flat);
            let general = c.solve_with(&k, 0.02625, 0.141, TOLERANCE, None, general);
            assert_eq!(fast, general, "{c:?} {k:?}");
        }
    }

    #[test]
    fn heuns_step_establishes_a_slip_as_the_full_integration_does() {
        // Over random impacts, many with a slip growing out of zero (a rolling ball's cloth
        // contact): the same results to the solver's accuracy, and the shortcut is taken.
        let mut rng = Rng(0x5eed_1234_abcd_0003);
        let without = Paths {
            flat: true,
            establish: false,
        };
        let (mut shortened, mut diffs) = (0, Vec::new());
        for case in 0..2_000 {
            let (c, mut k) = random_impact(&mut rng, case % 2 == 1);
            if case % 4 < 2 {
                // Rolling: the cloth slip under body 0 starts at zero.
                k.spin[0] = Vec3::z().cross(&k.vel[0]) / 0.02625;
            }
            let Ok(fast) = c.solve_with(&k, 0.02625, 0.141, TOLERANCE, None, Paths::FAST) else {
                continue;
            };
            let slow = c
                .solve_with(&k, 0.02625, 0.141, TOLERANCE, None, without)
                .unwrap();
            // The shortcut changes the results at rounding level where it is taken.
            shortened += usize::from(fast.after != slow.after);
            let scale = (k.vel[0] - k.vel[1]).norm();
            let diff = (0..2)
                .map(|i| {
                    let dv = (fast.after.vel[i] - slow.after.vel[i]).norm();
                    let dw = (fast.after.spin[i] - slow.after.spin[i]).norm() * 0.02625;
                    dv.max(dw) / scale
                })
                .fold(0.0, f64::max);
            diffs.push(diff);
        }
        // Where it was taken, the difference is of the order of the tolerance, and nowhere
        // near the solver's accuracy (1e-6 of V; these frictions reach 0.6).
        diffs.retain(|&d| d > 0.0);
        diffs.sort_by(f64::total_cmp);
        let n = diffs.len();
        assert!(n > 300 && shortened == n, "{shortened} impacts shortened");
        assert!(diffs[n / 2] < 1e-8, "median {:e}", diffs[n / 2]);
        assert!(diffs[n - 1] < 1e-6, "worst {:e}", diffs[n - 1]);
    }

    #[test]
    fn slips_are_measured_relative_to_their_size() {
        // The same error in a slip: accepted on a large slip, rejected on one near zero,
        // where it would turn the friction's direction.
        let c = Contact {
            bodies: [Body::ball(true), Body::fixed()],
            normal: -Vec3::y(),
            arm: [-Vec3::y(), Vec3::zeros()],
            mu: 0.14,
            mu_cloth: 0.2,
            e: 0.98,
        };
        let tol = 1e-9;
        let measure = c.measure(tol);
        let mut err = [0.0; N];
        err[0] = 5.0 * tol; // along x: changes the nose's and the cloth's slip
        let mut large = [0.0; N];
        large[0] = 1.0;
        let mut small = [0.0; N];
        small[0] = 1e-8;
        assert!(measure.measure(&large, &large, &err) < 1.0);
        assert!(measure.measure(&small, &small, &err) > 1.0);
    }
}
