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
/// A dying slip's tolerance per step, in units of `tol` (see [`SlipAware`]): at 10, 200,000
/// random impacts of each model are as accurate as when it was held to `tol` (medians better,
/// worst 2.2e-7 and 6.4e-7 of V); at 30 (the velocities') an airborne ball coming down on a
/// ball on the cloth with spins of 3 V/R was off by 1.1e-6 (docs/impact-convergence.md).
const DYING_SLIP_PER_TOLERANCE: f64 = 10.0;

/// The impacts' measure of a step's error. Velocities and spins are held to a tolerance
/// (absolute and relative) `VELOCITY_PER_SLIP_TOLERANCE` times `tol`. What friction reads
/// from a slip, though, is its direction, whose error is the slip's error over its size: each
/// slip is held to `tol (1 + VELOCITY_PER_SLIP_TOLERANCE |slip|)`, so that a large slip is
/// followed as loosely as the velocities and one near zero, where a stick, a release or a
/// reversal is decided, to `tol` itself.
///
/// Except a slip dying out (smaller at the step's end than at its start), held to
/// [`DYING_SLIP_PER_TOLERANCE`] `tol` whatever its size: its direction's error, e / |s|,
/// steers friction only until the slip is gone, over an impulse |s| / r (r its rate of decay),
/// so the velocities inherit e mu / r, with mu / r of order one wherever friction kills the
/// slip briskly (one that friction barely overcomes is followed quasi-statically, `mode.rs`).
/// Held to `tol`, a slip dying as it turns (the contact's mobility is not isotropic) took a
/// step per fraction of each e-fold of its decay: 60-90 steps for such a ball-ball impact.
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
        let before = (self.slips)(y0);
        for k in 0..3 {
            let size = slip[k].norm();
            let scale = if size < before[k].norm() {
                DYING_SLIP_PER_TOLERANCE * self.tol
            } else {
                self.tol + loose * size
            };
            let r = slip_err[k].norm() / scale;
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
