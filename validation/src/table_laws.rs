//! The table laws rapier lacks, as external loads applied each step: rolling resistance and
//! the cloth's resistance to sidespin. Each load is the one that makes rapier's equations of
//! motion reproduce the law as our engine states it, clamped so that one step never reverses
//! the motion it resists.

use snooker_engine::{Params, Vec3};

/// A force through the centre and a torque, N and N m, table frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Load {
    /// Force through the ball's centre.
    pub force: Vec3,
    /// Torque about the centre.
    pub torque: Vec3,
}

impl Load {
    /// No load.
    pub fn zero() -> Load {
        Load {
            force: Vec3::zeros(),
            torque: Vec3::zeros(),
        }
    }

    /// The sum of two loads.
    pub fn plus(self, other: Load) -> Load {
        Load {
            force: self.force + other.force,
            torque: self.torque + other.torque,
        }
    }
}

/// Rolling resistance on a rolling ball with horizontal velocity `vel`, for a step of `dt`,
/// the ball rolling on a contact point `arm` below its centre (R on a rigid cloth; rapier's
/// soft contact puts it at mid-depth, R - sink/2).
///
/// The law (thesis §2.4.2, mu_r from §5.1.1.1): the centre decelerates at mu_r g along its
/// path while the ball keeps rolling, w = (e_z x v) / arm. Differentiating both: the load is
/// F = -M mu_r g v^ through the centre and T = -(I mu_r g / arm) (e_z x v^), which keeps the
/// contact point at rest without any help from the cloth's friction (with the arm R on a sunk
/// ball the cloth's static friction would make up the difference and the ball would
/// decelerate at mu_r g (1 - 2 sink / 7R) instead). Within the last step of the roll the load
/// is scaled down to stop the ball exactly.
pub fn rolling_resistance(vel: Vec3, p: &Params, dt: f64, arm: f64) -> Load {
    let v = Vec3::new(vel.x, vel.y, 0.0);
    let speed = v.norm();
    if speed == 0.0 {
        return Load::zero();
    }
    let decel = (p.mu_roll * p.g).min(speed / dt);
    let dir = v / speed;
    Load {
        force: -p.ball_mass * decel * dir,
        torque: -(p.inertia() * decel / arm) * Vec3::z().cross(&dir),
    }
}

/// The cloth's resistance to spin about the vertical for a ball spinning at `wz` rad/s, for a
/// step of `dt`: a torque -I (dw_z/dt) e_z with |dw_z/dt| = `sidespin_decel`, whatever the
/// linear motion (thesis §2.4.2 "decoupled motion", rate from §5.3), scaled down within the
/// last step so that the spin stops at zero.
pub fn sidespin_resistance(wz: f64, p: &Params, dt: f64) -> Load {
    if wz == 0.0 {
        return Load::zero();
    }
    let decel = p.sidespin_decel.min(wz.abs() / dt);
    Load {
        force: Vec3::zeros(),
        torque: Vec3::new(0.0, 0.0, -p.inertia() * decel * wz.signum()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rolling_load_keeps_rolling() {
        let p = Params::default();
        let v = Vec3::new(0.6, -0.8, 0.0);
        let arm = p.ball_radius - 3.5e-5;
        let l = rolling_resistance(v, &p, 1e-4, arm);
        let dv = l.force / p.ball_mass;
        let dw = l.torque / p.inertia();
        // Deceleration mu_r g along -v^, and dw = e_z x dv / arm (rolling is kept).
        assert!((dv.norm() - p.mu_roll * p.g).abs() < 1e-12);
        assert!((dw - Vec3::z().cross(&dv) / arm).norm() < 1e-12);
        // Last step: stops the ball exactly.
        let slow = Vec3::new(1e-6, 0.0, 0.0);
        let l = rolling_resistance(slow, &p, 1e-4, p.ball_radius);
        assert!((slow + 1e-4 * l.force / p.ball_mass).norm() < 1e-18);
    }

    #[test]
    fn sidespin_load_decays_and_stops_at_zero() {
        let p = Params::default();
        let l = sidespin_resistance(-10.0, &p, 1e-4);
        assert!((l.torque.z / p.inertia() - p.sidespin_decel).abs() < 1e-9);
        let l = sidespin_resistance(1e-4, &p, 1e-4);
        assert!((1e-4 + 1e-4 * l.torque.z / p.inertia()).abs() < 1e-15);
    }
}
