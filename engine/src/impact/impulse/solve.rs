//! The impact, phase by phase (thesis §6.1.4, §6.2.4): each phase runs under one friction
//! mode until a switch (an [`Event`]); compression ends where the normal velocity vanishes,
//! the impact where the work of the normal impulse reaches (1 - e^2) of its value at the end
//! of compression (thesis eqs. 6.12, 6.38).

use super::error::ImpactError;
use super::events::Event;
use super::laws::Local;
use super::mode::{Mode, PRIMARY};
use super::pair::{FIXED_DIM, Fixed, Free, N, Pair, moving_bodies};
use super::problem::{Impact, Kinematics, Resolution, Sample};
use crate::ball::Vec3;
use crate::impact::dopri::Stop;

/// Tolerance of the integration (scaled units): that of the slips near zero, the velocities'
/// being 30 times larger (the step error measure, `impulse/measure.rs`). Results are within 1e-6
/// of the converged solution over random impacts with frictions up to 0.3 (worst 6.4e-7 in
/// 200,000; engine/tests/impact_models.rs, docs/impact-convergence.md).
pub const TOLERANCE: f64 = 5e-10;
/// A slip below this many integration tolerances (as a fraction of V) counts as zero: above
/// the integration's noise and the chatter of a contact about to stick (so a nil slip never
/// steers friction by its rounding), and far below the results' accuracy (1e-7 V at the
/// default tolerance).
const ZERO_SLIP_PER_TOLERANCE: f64 = 100.0;
/// Safety net: widest zero band (fraction of V) that a crawling or dithering integration may
/// escalate to. Not reached in any test; it bounds the cost of an unforeseen stiff case.
const WIDEST_ZERO: f64 = 1e-5;
/// Phases after which an impact counts as dithering: the zero band widens at every such count.
const DITHER_PHASES: usize = 20;
/// Most phases of one impact.
const MAX_PHASES: usize = 200;
/// Vertical speed (fraction of V) below which a ball at a support event has landed, and
/// within which a ball on the cloth at the start of a phase is at rest on it: the support
/// events' own resolution (`impulse/events.rs`).
const LANDED: f64 = 1e-12;

/// Which of the faster ways through an impact are taken: `reduce`, the state of a ball
/// against a fixed body at rest without the fixed body's velocities ([`Fixed`]; bitwise the
/// same results as the whole state's); `establish`, Heun's step for a slip growing out of zero
/// (`impulse/establish.rs`; the same results to the tolerance). The tests compare each with
/// the way round it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Paths {
    /// Leave a fixed body's velocities out of the state.
    pub reduce: bool,
    /// Establish a starting slip by Heun's step.
    pub establish: bool,
}

impl Paths {
    /// Every faster way.
    pub const FAST: Paths = Paths {
        reduce: true,
        establish: true,
    };
}

/// Where an impact's samples go, and the scales that make them dimensional.
pub(super) struct Recorder<'a, 'b> {
    pub trace: Option<&'a mut Vec<Sample>>,
    pub contact: &'b Impact,
    pub v_scale: f64,
    pub mass: f64,
}

impl Recorder<'_, '_> {
    /// Records the whole state `y` at impulse `p` (scaled) under `mode`.
    fn record(&mut self, p: f64, y: &[f64; N], mode: &Mode) {
        let Some(t) = self.trace.as_deref_mut() else {
            return;
        };
        let c = self.contact;
        let v_scale = self.v_scale;
        let loc: Local = c.local::<N, Free>(y);
        let reaction = c.forces::<N, Free>(y, &loc, mode).reaction;
        t.push(Sample {
            impulse: p * self.mass * v_scale,
            slip: loc.slip[PRIMARY] * v_scale,
            cloth_slip: [0, 1].map(|i| {
                if c.bodies[i].on_cloth {
                    Impact::cloth_slip::<N, Free>(y, i) * v_scale
                } else {
                    Vec3::zeros()
                }
            }),
            normal_velocity: loc.vn * v_scale,
            pressed: reaction.map(|r| r > 0.0),
        });
    }
}

impl Impact {
    /// The state vector in scaled units, and the velocity scale (the approach speed).
    pub(super) fn scaled(
        &self,
        k: &Kinematics,
        radius: f64,
    ) -> Result<([f64; N], f64), ImpactError> {
        let u0 = (k.vel[0] + k.spin[0].cross(&(radius * self.arm[0])))
            - (k.vel[1] + k.spin[1].cross(&(radius * self.arm[1])));
        let approach = u0.dot(&self.normal);
        if !(approach > 0.0 && approach.is_finite()) {
            return Err(ImpactError::NotApproaching {
                normal_speed: approach,
            });
        }
        let mut y = [0.0; N];
        for i in 0..2 {
            Free::put(
                &mut y,
                i,
                k.vel[i] / approach,
                k.spin[i] * radius / approach,
            );
        }
        Ok((y, approach))
    }

    /// The dimensional velocities of the whole state `y` (scaled by `v_scale`).
    pub(super) fn unscaled(&self, y: &[f64; N], v_scale: f64, radius: f64) -> Kinematics {
        Kinematics {
            vel: [0, 1].map(|i| Free::vel(y, i) * v_scale),
            spin: [0, 1].map(|i| Free::spin(y, i) * v_scale / radius),
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
    ) -> Result<Resolution, ImpactError> {
        self.solve_to(k, radius, mass, TOLERANCE, trace)
    }

    /// [`Impact::solve`] to a given tolerance `tol` (scaled units, as [`TOLERANCE`]: the
    /// slips' near zero, the velocities' 30 times larger; the zero band scales with it).
    pub fn solve_to(
        &self,
        k: &Kinematics,
        radius: f64,
        mass: f64,
        tol: f64,
        trace: Option<&mut Vec<Sample>>,
    ) -> Result<Resolution, ImpactError> {
        self.solve_with(k, radius, mass, tol, trace, Paths::FAST)
    }

    /// [`Impact::solve_to`], taking the faster `paths` given.
    pub(super) fn solve_with(
        &self,
        k: &Kinematics,
        radius: f64,
        mass: f64,
        tol: f64,
        trace: Option<&mut Vec<Sample>>,
        paths: Paths,
    ) -> Result<Resolution, ImpactError> {
        if !(0.0..).contains(&self.e) || !self.e.is_finite() {
            return Err(ImpactError::RestitutionOutOfRange { e: self.e });
        }
        // Scaled units: velocities / V, spins * R / V, impulse / (M V), work / (M V^2).
        let (y, v_scale) = self.scaled(k, radius)?;
        // The backing's energy and damping in the same units.
        let scaled_impact = Impact {
            backing: self.backing.map(|b| b.scaled(mass, v_scale)),
            ..*self
        };
        let this = &scaled_impact;
        let mut recorder = Recorder {
            trace,
            contact: this,
            v_scale,
            mass,
        };
        if recorder.trace.is_some() {
            let first = this.mode_at::<N, Free>(&y, true, 0.0, ZERO_SLIP_PER_TOLERANCE * tol);
            recorder.record(0.0, &y, &first);
        }
        // A fixed body at rest keeps its velocities (zero): only the other entries are
        // integrated, nearly halving the integrator's work, with the steps and results of the
        // whole state.
        let fixed_at_rest = !self.bodies[0].is_fixed()
            && self.bodies[1].is_fixed()
            && Free::vel(&y, 1) == Vec3::zeros()
            && Free::spin(&y, 1) == Vec3::zeros();
        let (y, outcome) = if paths.reduce && fixed_at_rest {
            let (z, outcome) =
                this.phases::<FIXED_DIM, Fixed>(Fixed::part(&y), tol, paths, &mut recorder)?;
            (Fixed::whole(&z), outcome)
        } else {
            this.phases::<N, Free>(y, tol, paths, &mut recorder)?
        };
        Ok(Resolution {
            after: self.unscaled(&y, v_scale, radius),
            impulse: outcome.impulse * mass * v_scale,
            compression_impulse: outcome.compression_impulse * mass * v_scale,
            ..outcome
        })
    }

    /// Sets to zero the vertical speed of each ball on the cloth that is within [`LANDED`] of
    /// it. A ball on the cloth is either held down by it or rising (thesis §6.1.2); the
    /// support event, zero within the same resolution, does not see a ball rising or sinking
    /// more slowly come back to the cloth, so the phase must not start with one: the cloth
    /// would start pressing on it mid-phase, with its friction off for the phase.
    fn land_resting<const M: usize, P: Pair<M>>(&self, y: &mut [f64; M]) {
        for i in 0..moving_bodies::<M, P>() {
            let (v, w) = (P::vel(y, i), P::spin(y, i));
            if self.bodies[i].on_cloth && v.z != 0.0 && v.z.abs() <= LANDED {
                P::put(y, i, Vec3::new(v.x, v.y, 0.0), w);
            }
        }
    }

    /// The phases of the impact from the scaled state `y` (of pair `P`) to the end of
    /// restitution: the final state, and the outcome with scaled impulses (its velocities are
    /// left for the caller).
    pub(super) fn phases<const M: usize, P: Pair<M>>(
        &self,
        mut y: [f64; M],
        tol: f64,
        paths: Paths,
        recorder: &mut Recorder<'_, '_>,
    ) -> Result<([f64; M], Resolution), ImpactError> {
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
            if phases > MAX_PHASES {
                return Err(ImpactError::TooManyPhases { limit: MAX_PHASES });
            }
            if phases % DITHER_PHASES == 0 {
                zero = (10.0 * zero).min(WIDEST_ZERO);
            }
            self.land_resting::<M, P>(&mut y);
            // A landing (here, or at a support event) changes a ball's vertical speed by less
            // than the events' resolution, and with the cushion's tilted normal, the normal
            // velocity by as little: one still approaching by 1e-13 may so come to part. That
            // is compression's end (thesis eq. 6.12), though no event crossed it: a phase of
            // compression that began already parting would never see the event, and push the
            // bodies apart without end.
            if compressing && self.primary_motion::<M, P>(&y).1 <= 0.0 {
                compressing = false;
                p_c = p;
                let Some(target) = self.restitution_target(y[P::WORK]) else {
                    break;
                };
                w_target = target;
            }
            let mode = self.mode_at::<M, P>(&y, compressing, w_target, zero);
            self.stop_residual_slips::<M, P>(&mut y, &mode);
            let ph = self.integrate_phase::<M, P>(&mode, p, y, h, tol, paths.establish, |x, yy| {
                if recorder.trace.is_some() {
                    recorder.record(x, &P::whole(yy), &mode)
                }
            });
            steps += ph.steps;
            if ph.x > 1e3 * p_guess.max(1.0) {
                return Err(ImpactError::UnboundedImpulse);
            }
            let Stop::Event(ev) = ph.stop else {
                // Crawling: a slip hovers at the edge of sticking (friction capacity and drive
                // in balance), where its direction is stiff at tiny slips. Whether it sticks
                // or creeps changes nothing measurable; widen the zero band and go on.
                if zero >= WIDEST_ZERO || ph.x <= p {
                    return Err(ImpactError::DidNotConverge);
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
            match Event::at(ev) {
                Event::Compressed => {
                    compressing = false;
                    p_c = p;
                    let Some(target) = self.restitution_target(y[P::WORK]) else {
                        break;
                    };
                    w_target = target;
                }
                Event::Restituted => break,
                Event::Slip(_) => {
                    // A slip turned, stopped or restarted: the next phase's mode says how.
                }
                Event::Support(_) => {
                    // Pressing or lifting changed. A ball coming back down within the impact
                    // (its vertical speed at the root is zero to the root tolerance) lands:
                    // the cloth holds it from here.
                    for i in 0..moving_bodies::<M, P>() {
                        let (v, w) = (P::vel(&y, i), P::spin(&y, i));
                        if self.bodies[i].on_cloth && v.z <= LANDED {
                            P::put(&mut y, i, Vec3::new(v.x, v.y, 0.0), w);
                        }
                    }
                }
            }
        }
        let outcome = Resolution {
            after: Kinematics {
                vel: [Vec3::zeros(); 2],
                spin: [Vec3::zeros(); 2],
            },
            impulse: p,
            compression_impulse: p_c,
            steps,
            phases,
        };
        Ok((y, outcome))
    }
}
