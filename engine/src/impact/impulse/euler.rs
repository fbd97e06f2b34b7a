//! The thesis's own scheme, for comparison (thesis §6.1.4.2, §6.2.4): forward Euler in P.

use super::error::ImpactError;
use super::laws::NONE_HELD;
use super::mode::{Friction, Mode};
use super::pair::{Free, N, WORK};
use super::problem::{Impact, Kinematics};

impl Impact {
    /// The thesis's scheme: forward Euler in P with `steps` equal increments of the
    /// frictionless impulse, friction against the slip of the step's start, compression and
    /// restitution work by the trapezoidal rule (eq. 6.16). First order: its error falls as
    /// 1/steps.
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
            let mut mode = Mode::new([Friction::Off; 3], compressing, target, 0.0);
            let loc = self.local::<N, Free>(&y);
            for kk in 0..3 {
                let s = loc.slip[kk];
                if self.coefficient(kk) > 0.0 && s.norm() > 0.0 {
                    mode.friction[kk] = Friction::Slip(s.normalize());
                }
            }
            let vn0 = loc.vn;
            let forces = self.forces_with::<N, Free>(&y, loc.slip[0], &mode, &NONE_HELD);
            let dy = self.derivatives::<N, Free>(vn0, &forces);
            for (v, d) in y.iter_mut().zip(dy) {
                *v += dp * d;
            }
            let vn1 = self.primary_motion::<N, Free>(&y).1;
            y[WORK] += dp * (0.5 * (vn0 + vn1) - vn0);
            if compressing && vn1 <= 0.0 {
                compressing = false;
                target = (1.0 - self.e * self.e) * y[WORK];
            }
            if !compressing && y[WORK] <= target {
                return Ok(self.unscaled(&y, v_scale, radius));
            }
        }
        Err(ImpactError::EulerDidNotFinish)
    }
}
