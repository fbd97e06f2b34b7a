//! Effects of a real cloth and bed beyond the thesis's laws, all off by default; the
//! discrepancy workflow's catalogue switches them on:
//! - a bed that is not level: gravity's component along the cloth, g (slope_x, slope_y);
//! - the cloth's nap: a sideways acceleration nap_drift (v^.x)(v^ x z) on a moving ball, so a
//!   ball travelling along the table (with or against the nap, which runs along x) drifts
//!   towards -y (the right-hand side seen from baulk) in proportion to how much it travels
//!   along x, one travelling across it does not (the effect the thesis cites from Williams
//!   2002, §5.1.1.1, and did not see in its data);
//! - sliding friction that grows with the slip speed, from mu_slide_low at rest towards
//!   mu_slide: mu(s) = mu_slide - (mu_slide - mu_slide_low) exp(-s / slide_speed_scale)
//!   (Witters and Duymelinck 1986: 0.14 rising towards 0.21; thesis §2.4.2, §5.1.1.2).
//!
//! With any of them on, a ball's path is no longer a polynomial in time. The laws then hold
//! their accelerations over short segments (at most [`SEGMENT`] long), taken at the segment's
//! middle (the midpoint rule, second order), and a segment's end renews them: every path stays
//! a quadratic and every event stays exact for it. Against a fine integration of the
//! continuous laws a 13 m roll across a tilted bed ends within 2 micrometres
//! (tests/cloth_effects.rs).

use crate::ball::Vec3;
use crate::params::Params;

/// Longest segment over which the extra accelerations are held, s.
pub const SEGMENT: f64 = 0.01;

/// True when any effect of this module is on.
pub fn active(p: &Params) -> bool {
    p.slope_x != 0.0 || p.slope_y != 0.0 || p.nap_drift != 0.0 || speed_dependent(p)
}

/// True when the sliding friction depends on the slip speed.
pub fn speed_dependent(p: &Params) -> bool {
    p.slide_speed_scale > 0.0 && p.mu_slide_low != p.mu_slide
}

/// Sliding friction coefficient at slip speed `slip`, m/s.
pub fn mu_slide(p: &Params, slip: f64) -> f64 {
    if speed_dependent(p) {
        p.mu_slide - (p.mu_slide - p.mu_slide_low) * (-slip / p.slide_speed_scale).exp()
    } else {
        p.mu_slide
    }
}

/// Acceleration of a ball's centre from the bed's tilt (m/s^2, horizontal).
pub fn slope(p: &Params) -> Vec3 {
    Vec3::new(p.g * p.slope_x, p.g * p.slope_y, 0.0)
}

/// Sideways acceleration from the nap on a ball moving along the unit vector `dir` (zero at rest).
pub fn nap(p: &Params, dir: Vec3) -> Vec3 {
    if p.nap_drift == 0.0 || dir.norm() == 0.0 {
        return Vec3::zeros();
    }
    p.nap_drift * dir.x * dir.cross(&Vec3::z())
}

/// The acceleration the bed and the nap give a ball moving along `dir` (through its centre).
pub fn body_acceleration(p: &Params, dir: Vec3) -> Vec3 {
    slope(p) + nap(p, dir)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn friction_rises_with_slip_towards_mu_slide() {
        let p = Params {
            mu_slide_low: 0.14,
            slide_speed_scale: 0.5,
            ..Params::default()
        };
        assert!((mu_slide(&p, 0.0) - 0.14).abs() < 1e-15);
        assert!(mu_slide(&p, 0.5) > 0.18 && mu_slide(&p, 0.5) < 0.21);
        assert!((mu_slide(&p, 10.0) - 0.21).abs() < 1e-9);
        assert!(!active(&Params::default()));
    }

    #[test]
    fn nap_pushes_to_the_right_along_the_table_and_not_across() {
        let p = Params {
            nap_drift: 0.01,
            ..Params::default()
        };
        assert!(nap(&p, Vec3::x()).y < 0.0);
        assert!(nap(&p, -Vec3::x()).y < 0.0);
        assert_eq!(nap(&p, Vec3::y()), Vec3::zeros());
    }
}
