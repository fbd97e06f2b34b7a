//! Spin about the vertical ("sidespin"): decays linearly at a fixed rate whatever the
//! linear motion ("decoupled motion", thesis §2.4.2 and §7.1.1.2, rate measured in §5.3).
//! A ball at rest that spins follows this law alone.

use crate::ball::BallState;
use crate::params::Params;

/// Sidespin after `dt` seconds: |w_z| falls at `decel` rad/s^2 and stays at zero once there
/// (thesis eq. 45a/45b).
pub fn sidespin_at(wz: f64, dt: f64, decel: f64) -> f64 {
    let left = wz.abs() - decel * dt;
    if left <= 0.0 { 0.0 } else { left.copysign(wz) }
}

/// Time for sidespin `wz` to decay to zero, s (infinite without resistance).
pub fn sidespin_duration(wz: f64, decel: f64) -> f64 {
    if wz == 0.0 {
        0.0
    } else if decel > 0.0 {
        wz.abs() / decel
    } else {
        f64::INFINITY
    }
}

/// State of a spinning (otherwise resting) ball after `dt`.
pub fn state_at(s: &BallState, dt: f64, p: &Params) -> BallState {
    let mut out = *s;
    out.spin.z = sidespin_at(s.spin.z, dt, p.sidespin_decel);
    out
}

/// How long the spinning phase lasts.
pub fn duration(s: &BallState, p: &Params) -> f64 {
    sidespin_duration(s.spin.z, p.sidespin_decel)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decays_linearly_to_zero_and_stays() {
        assert_eq!(sidespin_at(10.0, 0.1, 22.0), 10.0 - 2.2);
        assert_eq!(sidespin_at(-10.0, 0.1, 22.0), -10.0 + 2.2);
        assert_eq!(sidespin_at(10.0, 1.0, 22.0), 0.0);
        assert!((sidespin_duration(-11.0, 22.0) - 0.5).abs() < 1e-15);
    }
}
