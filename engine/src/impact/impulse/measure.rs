//! The impacts' measure of a step's error: slip-aware, because friction reads a slip's
//! direction (docs/impact-convergence.md).

use super::pair::N;
use super::problem::Impact;
use crate::ball::Vec3;
use crate::impact::dopri::{self, ErrorMeasure};

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
pub(super) struct SlipAware<S> {
    tol: f64,
    /// Velocities' tolerance over `tol`.
    loose: f64,
    /// Components the velocities' mean is taken over (those of the whole state, also when a
    /// fixed body's constant ones are left out).
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

impl Impact {
    /// The error measure, to tolerance `tol`, of a step of a state whose slips are `slips`
    /// (linear in the state, so that they also give an error's slips).
    pub(super) fn measure<S>(&self, tol: f64, slips: S) -> SlipAware<S> {
        SlipAware {
            tol,
            loose: VELOCITY_PER_SLIP_TOLERANCE,
            dim: N,
            slips,
        }
    }
}
