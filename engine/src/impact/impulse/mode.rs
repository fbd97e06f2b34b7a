//! How each frictional contact behaves during a phase (slipping, at zero slip, or creeping out
//! of zero), and the mode an impact is in at a state.
//!
//! Friction is Coulomb's law (thesis §6.1.2.1, §6.2.2.1): against the slip while there is one;
//! at zero slip the contact holds if the friction needed is at most mu N, and otherwise creeps
//! out of zero ([`super::coulomb`]). A slip below the zero band counts as zero, so that noise
//! in a nil slip never steers friction.

use super::events::RESOLUTION;
use super::laws::{Held, Local, NONE_HELD};
use super::pair::Pair;
use super::problem::Impact;
use crate::ball::Vec3;

/// A creeping slip growing faster than this (fraction of V per unit impulse M V) is robust:
/// its direction can be frozen while it grows out of the zero band.
const ROBUST_CREEP: f64 = 1e-1;
/// A slip growing out of zero is followed as a slip once it exceeds this many zero bands.
/// Until then its direction is the quasi-static creep's, which lags a slow creep's own: at 100
/// the worst of 200,000 random cushion impacts was off by 2e-6, at 10 by 5.5e-7; lower only
/// costs steps (docs/impact-convergence.md). Once established, a slow creep whose steady
/// direction barely turns goes on being followed quasi-statically
/// ([`Impact::follow_slow_slips`]).
pub(super) const ESTABLISHED_PER_ZERO: f64 = 10.0;
/// A slow slip is followed quasi-statically while the lag of its direction, s omega / |d|
/// (radians; [`Impact::follow_slow_slips`]), is below this many zero bands: friction then errs
/// by at most mu N times that, far below the results' accuracy.
const LAG_PER_ZERO: f64 = 1.0;
/// Largest slip (fraction of V) followed quasi-statically: a bound, not a tuning (a creep
/// whose direction does not turn at all is followed so to the end of the impact).
const WIDEST_QUASI_STATIC: f64 = 1.0;
/// Slips (fraction of V) below which a slow one may be followed quasi-statically: a larger
/// one relaxes onto its steady direction over more than 1 % of the impact's impulse (drives
/// |d| being about 1), which an explicit integrator follows in a few hundred steps at most.
const STIFF_SLIP: f64 = 1e-2;
/// Impulse (units of M V) over which the turn of a creep's direction is measured: small
/// against any phase, large against rounding (1e-16 / this is the smallest turn rate seen).
const TURN_PROBE: f64 = 1e-6;

/// The frictional contacts: the primary one, then the cloth under body 0 and under body 1.
pub(super) const PRIMARY: usize = 0;
/// The cloth contact under body `i` is frictional contact `CLOTH[i]`.
pub(super) const CLOTH: [usize; 2] = [1, 2];

/// How a frictional contact behaves during a phase.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Friction {
    /// No friction (zero coefficient, or no normal force).
    Off,
    /// Slipping: friction mu N against the slip; the slip's direction when the phase began.
    Slip(Vec3),
    /// At zero slip: holding, or creeping out of zero, as Coulomb's law decides at every
    /// instant ([`Impact::at_zero`]).
    AtZero,
    /// Creeping robustly out of zero: friction mu N against this (consistent) direction until
    /// the slip is established; the direction cannot change in that instant.
    Starting(Vec3),
    /// Slipping slowly, out of zero or down to it, along the slip's steady direction: the one
    /// in which its rate is along it, that its own direction relaxes onto over an impulse s /
    /// |d| (slip s, drive |d|). Friction mu N against that direction, found by the Coulomb
    /// solve ([`Impact::at_zero`]); [`Impact::follow_slow_slips`] says why and when. The
    /// slip's direction when the phase began, to see it come down to zero, and the sign of
    /// its rate then (1 growing, -1 shrinking): the phase ends where that changes, so that a
    /// step never takes the slip down through zero and back.
    QuasiStatic(Vec3, f64),
}

/// The mode of one phase: each contact's friction, and the stage of restitution.
#[derive(Clone, Copy, Debug)]
pub(super) struct Mode {
    /// The frictional contacts' laws ([`PRIMARY`], then [`CLOTH`]).
    pub friction: [Friction; 3],
    /// Whether the normal velocity is still approaching (compression).
    pub compressing: bool,
    /// Work at which restitution ends (thesis eq. 6.38).
    pub w_target: f64,
    /// Slip (fraction of V) below which a slip counts as zero.
    pub zero: f64,
    /// Per contact: the slip (fraction of V) at which a contact at zero, starting, or followed
    /// quasi-statically is established, and followed as a slip ([`ESTABLISHED_PER_ZERO`] zero
    /// bands, or, followed quasi-statically, [`Impact::follow_slow_slips`]'s bound).
    pub established: [f64; 3],
    /// Per contact: the steady direction a slow slip is relaxing onto, if it is to be
    /// followed quasi-statically once it lies along it ([`Impact::follow_slow_slips`]).
    pub aligning: [Option<Vec3>; 3],
}

impl Mode {
    /// A mode with every contact's friction `friction`, and the zero band `zero`.
    pub fn new(friction: [Friction; 3], compressing: bool, w_target: f64, zero: f64) -> Mode {
        Mode {
            friction,
            compressing,
            w_target,
            zero,
            established: [ESTABLISHED_PER_ZERO * zero; 3],
            aligning: [None; 3],
        }
    }

    /// Whether a contact's friction needs the Coulomb solve: one at zero slip, or followed
    /// quasi-statically.
    pub fn any_at_zero(&self) -> bool {
        self.friction
            .iter()
            .any(|law| matches!(law, Friction::AtZero | Friction::QuasiStatic(..)))
    }
}

/// Direction of a slip: its own while it is measurably non-zero (above `zero`), otherwise
/// `chosen` (the direction the phase began with), so that noise in a nil slip never steers
/// friction.
#[inline(always)]
pub(super) fn slip_direction(s: Vec3, chosen: Vec3, zero: f64) -> Vec3 {
    let n = s.norm();
    if n <= zero {
        return chosen;
    }
    // One division and three products rather than three divisions: the slopes are a chain of
    // dependent evaluations, and a division is slow.
    let d = s * (1.0 / n);
    // A slip that has come down through zero within a step (turned by more than 135 degrees
    // from the phase's direction) keeps the law it had along that direction: the phase ends at
    // that zero (its event), and a law continued smoothly past it lets the step that
    // overshoots be accepted and the zero located on the step's interpolant, rather than
    // refused until the steps creep up on it. Mirrored, not reversed: across the direction
    // the slip's part keeps its side of the zero, as it does passing by it, so that a slip
    // dying along its direction steers friction across it exactly as the exact law does.
    let along = d.dot(&chosen);
    if along < -std::f64::consts::FRAC_1_SQRT_2 {
        d - (2.0 * along) * chosen
    } else {
        d
    }
}

/// Friction of a contact under `law` whose slip is `s`, its capacity (mu N) being `cap`;
/// `held`, the Coulomb solve's, if it is at zero slip.
#[inline(always)]
pub(super) fn friction(
    law: Friction,
    cap: f64,
    s: impl FnOnce() -> Vec3,
    zero: f64,
    held: Vec3,
) -> Vec3 {
    match law {
        Friction::Off => Vec3::zeros(),
        Friction::Slip(r) => -cap * slip_direction(s(), r, zero),
        Friction::Starting(r) => -cap * r,
        Friction::AtZero | Friction::QuasiStatic(..) => held,
    }
}

impl Impact {
    /// The mode at state `y`: a contact slips if its slip is measurable, otherwise it is at
    /// zero (holding or creeping, decided continuously), or has no friction at all.
    pub(super) fn mode_at<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        compressing: bool,
        w_target: f64,
        zero: f64,
    ) -> Mode {
        let loc = self.local::<M, P>(y);
        let mut mode = Mode::new([Friction::Off; 3], compressing, w_target, zero);
        for k in 0..3 {
            let on_cloth = k == PRIMARY || self.bodies[k - 1].on_cloth;
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
        let f = if mode.friction[PRIMARY] == Friction::AtZero {
            self.forces::<M, P>(y, &loc, &mode)
        } else {
            self.forces_with::<M, P>(y, loc.slip[PRIMARY], &mode, &NONE_HELD)
        };
        for (reaction, k) in f.reaction.into_iter().zip(CLOTH) {
            if reaction <= 0.0 {
                mode.friction[k] = Friction::Off;
            }
        }
        // A contact creeping out of zero fast (its slip growing at more than ROBUST_CREEP per
        // unit impulse) keeps its direction until established.
        let (held, creeping) = self.at_zero::<M, P>(y, &loc, &mode);
        for (law, creep) in mode.friction.iter_mut().zip(creeping) {
            if let Some(c) = creep.filter(|c| c.rate > ROBUST_CREEP) {
                *law = Friction::Starting(c.dir);
            }
        }
        self.follow_slow_slips::<M, P>(y, &loc, &held, &mut mode);
        mode
    }

    /// Follows quasi-statically ([`Friction::QuasiStatic`]) the small slips that grow out of
    /// zero or come down to it slowly (at most at [`ROBUST_CREEP`]) along their steady
    /// directions, while those turn slowly. A slip s changing at lambda per unit impulse, its
    /// drive (its rate without its own friction) being |d|, relaxes onto its steady direction
    /// over an impulse s / |d|: followed as a slip, its direction is stiff, and an explicit
    /// integrator needs about |d| / (3 s) steps per unit impulse (hundreds of thousands where
    /// the friction barely loses or wins against its drive, as the cloth's under a ball on it
    /// against a cushion whose mu_s is near (5/7) cos(theta): with the nose at 7R/5 (thesis
    /// §6.2) a horizontal force there leaves the cloth slip alone, and a vertical one needs
    /// that ratio of cloth friction to reaction, whatever the cushion's friction does).
    /// Followed quasi-statically, its direction is the steady one, which the slip's own
    /// lags by s omega / |d| (omega: the steady direction's turn rate): it is followed so
    /// while that lag is within [`LAG_PER_ZERO`] zero bands, at most to [`WIDEST_QUASI_STATIC`].
    /// `held`: the frictions of the contacts at zero (and starting) under `mode`.
    fn follow_slow_slips<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        loc: &Local,
        held: &Held,
        mode: &mut Mode,
    ) {
        // Candidates: small slips changing slowly under their own laws (no Coulomb solve
        // needed to tell).
        let mut rates = None;
        for k in 0..3 {
            let (s, n) = (loc.slip[k], loc.slip[k].norm());
            if !(matches!(mode.friction[k], Friction::Slip(_)) && n < STIFF_SLIP) {
                continue;
            }
            // The frictions at zero are `held` (a starting contact's too).
            let dy = *rates.get_or_insert_with(|| {
                let f = self.forces_with::<M, P>(y, loc.slip[PRIMARY], mode, held);
                self.derivatives::<M, P>(loc.vn, &f)
            });
            // Along its steady direction a slip changes at lambda; off it by an angle alpha,
            // its rate along itself differs from lambda by |d| (1 - cos alpha), less than its
            // rate across itself, |d| sin alpha.
            let rate = self.slip_rate::<M, P>(&dy, k);
            let growth = rate.dot(&s) / n;
            let across = (rate - growth * s / n).norm();
            let slow = growth.abs() <= ROBUST_CREEP + across;
            if !slow {
                continue;
            }
            let mut trial = *mode;
            trial.friction[k] = Friction::QuasiStatic(s / n, 1.0);
            let Some(steady) = self.at_zero::<M, P>(y, loc, &trial).1[k] else {
                continue;
            };
            let along = s.dot(&steady.dir);
            if !(steady.rate.abs() <= ROBUST_CREEP && along > 0.0) {
                continue;
            }
            // The steady direction's turn rate, over a small impulse along the slopes.
            let f = self.forces::<M, P>(y, loc, &trial);
            let dy = self.derivatives::<M, P>(loc.vn, &f);
            let mut ahead = *y;
            for (a, d) in ahead.iter_mut().zip(dy) {
                *a += TURN_PROBE * d;
            }
            let ahead_loc = self.local::<M, P>(&ahead);
            let Some(turned) = self.at_zero::<M, P>(&ahead, &ahead_loc, &trial).1[k] else {
                continue;
            };
            let omega = (turned.dir - steady.dir).norm() / TURN_PROBE;
            let until = (LAG_PER_ZERO * mode.zero * steady.drive / omega).min(WIDEST_QUASI_STATIC);
            // Only well within that, so that a phase that ended where the lag reached its
            // bound does not start another.
            if s.norm() >= 0.5 * until {
                continue;
            }
            // The steady direction's friction is the slip's own only once the slip lies along
            // it (within the zero band); until then the slip is followed as one, to there.
            if (s - along * steady.dir).norm() <= 2.0 * mode.zero {
                // At a root of the rate (where a phase ends as it changes sign), the rate's
                // own sign is rounding: the trend, a probe ahead, says which side comes next.
                let rate = if steady.rate.abs() <= RESOLUTION {
                    turned.rate
                } else {
                    steady.rate
                };
                mode.friction[k] = Friction::QuasiStatic(s / n, rate.signum());
                mode.established[k] = until;
            } else {
                mode.aligning[k] = Some(steady.dir);
            }
        }
    }
}
