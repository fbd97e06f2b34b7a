//! How each frictional contact behaves during a phase (slipping, at zero slip, or creeping out
//! of zero), and the mode an impact is in at a state.
//!
//! Friction is Coulomb's law (thesis §6.1.2.1, §6.2.2.1): against the slip while there is one;
//! at zero slip the contact holds if the friction needed is at most mu N, and otherwise creeps
//! out of zero ([`super::coulomb`]). A slip below the zero band counts as zero, so that noise
//! in a nil slip never steers friction.

use super::laws::NONE_HELD;
use super::pair::Pair;
use super::problem::Impact;
use crate::ball::Vec3;

/// A creeping slip growing faster than this (fraction of V per unit impulse M V) is robust:
/// its direction can be frozen while it grows out of the zero band.
const ROBUST_CREEP: f64 = 1e-1;
/// A slip growing out of zero is followed as a slip once it exceeds this many zero bands.
/// Until then its direction is the quasi-static creep's, which lags a slow creep's own: at 100
/// the worst of 200,000 random cushion impacts was off by 2e-6, at 10 by 5.5e-7; lower only
/// costs steps (docs/impact-convergence.md).
pub(super) const ESTABLISHED_PER_ZERO: f64 = 10.0;

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
}

impl Mode {
    /// Whether a contact is at zero slip (its friction then needs the Coulomb solve).
    pub fn any_at_zero(&self) -> bool {
        self.friction.contains(&Friction::AtZero)
    }
}

/// Direction of a slip: its own while it is measurably non-zero (above `zero`), otherwise
/// `chosen` (the direction the phase began with), so that noise in a nil slip never steers
/// friction.
#[inline(always)]
pub(super) fn slip_direction(s: Vec3, chosen: Vec3, zero: f64) -> Vec3 {
    let n = s.norm();
    // One division and three products rather than three divisions: the slopes are a chain of
    // dependent evaluations, and a division is slow.
    if n > zero { s * (1.0 / n) } else { chosen }
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
        Friction::AtZero => held,
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
        let mut mode = Mode {
            friction: [Friction::Off; 3],
            compressing,
            w_target,
            zero,
        };
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
        let (_, creeping) = self.at_zero::<M, P>(y, &loc, &mode);
        for (law, creep) in mode.friction.iter_mut().zip(creeping) {
            if let Some((dir, _)) = creep.filter(|c| c.1 > ROBUST_CREEP) {
                *law = Friction::Starting(dir);
            }
        }
        mode
    }
}
