//! Physical parameters, their defaults and where each default comes from.
//!
//! All values are SI. Defaults are the thesis's measured or fitted values
//! (Mathavan, "Trajectory solutions for a game-playing robot...", cited as
//! "thesis §x.y"); the few that the thesis does not give are marked as
//! assumptions with their reason.

use serde::{Deserialize, Serialize};

/// Every physical parameter of a shot.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Params {
    /// Gravitational acceleration, m/s^2.
    pub g: f64,
    /// Ball mass M, kg (thesis §6.1.4.2).
    pub ball_mass: f64,
    /// Ball radius R, m (thesis §6.1.4.2).
    pub ball_radius: f64,
    /// Ball-cloth sliding friction mu_s (thesis §5.1.1.2, mean of 0.178-0.245).
    pub mu_slide: f64,
    /// Rolling resistance mu_r: deceleration / g while rolling (thesis §5.1.1.1, 0.0127-0.0129).
    pub mu_roll: f64,
    /// Angular deceleration of sidespin (spin about the vertical), rad/s^2 (thesis §5.3, 21.8 "in the range of 22").
    pub sidespin_decel: f64,
    /// Ball-ball restitution e (thesis §6.1.4.3, fitted to the head-on data).
    pub e_ball: f64,
    /// Ball-ball friction mu_bb (thesis §6.1.4.3).
    pub mu_ball: f64,
    /// Ball-cushion restitution e_e (thesis §6.2.5.1).
    pub e_cushion: f64,
    /// Ball-cushion friction mu_w (thesis §6.2.5.1).
    pub mu_cushion: f64,
    /// Height of the cushion nose above the cloth, m (thesis §6.2: h = 7R/5; AJP paper: 36 mm).
    pub cushion_height: f64,
    /// Effective mass of the cue at the tip along its axis, kg. Assumption: a typical
    /// 19 oz (0.54 kg) snooker cue; the arm does not take part in the ~1 ms impact (Cross 2008).
    pub cue_mass: f64,
    /// Cue tip radius, m (thesis §7.1.2: 10 mm).
    pub cue_tip_radius: f64,
    /// Cue tip-ball restitution, fitted so that a centre hit gives the measured
    /// ball/cue speed ratio of 1.45 with `cue_mass` (thesis §5.1.4).
    pub cue_tip_restitution: f64,
    /// Transverse "end mass" of the cue tip, kg, fitted so that a 12 mm side offset gives
    /// the thesis's 2.5 degree squirt (thesis §2.4.1.3; squirt model of Shepard 1997 / Cross 2008).
    pub cue_endmass: f64,
    /// Largest contact offset from the cue axis, as a fraction of R, before a miscue
    /// (thesis §7.1.2 eq. 7.7, after Alciatore: R/2).
    pub miscue_limit: f64,
    /// Tilt of the bed along x, rad (a ball feels g slope_x towards +x). Off (0) by default;
    /// the thesis's table is taken as level. See [`crate::motion::cloth`].
    pub slope_x: f64,
    /// Tilt of the bed along y, rad. Off (0) by default.
    pub slope_y: f64,
    /// Sideways acceleration of the cloth's nap, m/s^2 ([`crate::motion::cloth::nap`]). Off
    /// (0) by default: the thesis found no nap effect (§5.1.1.1).
    pub nap_drift: f64,
    /// Sliding friction at zero slip (Witters and Duymelinck: 0.14); equal to `mu_slide` (no
    /// speed dependence) by default, as the thesis measured none (§5.1.1.2).
    pub mu_slide_low: f64,
    /// Slip speed over which sliding friction rises from `mu_slide_low` to `mu_slide`, m/s
    /// (0 = no speed dependence, the default).
    pub slide_speed_scale: f64,
    /// Fall of the cushion's restitution with the normal impact speed above
    /// `e_cushion_knee`, per m/s: e_e(v) = e_cushion - e_cushion_falloff (v - knee). Off (0) by
    /// default; the thesis's rigid model holds below about 2.5 m/s (§6.2.5).
    pub e_cushion_falloff: f64,
    /// Normal speed above which the cushion's restitution falls, m/s (thesis §6.2.5.1: e_e
    /// was fitted below 1.5 m/s).
    pub e_cushion_knee: f64,
}

/// Thesis §5.1.4: ball speed / cue speed for a centre-ball (stun) strike.
pub const CENTRE_SPEED_TRANSFER: f64 = 1.45;

impl Default for Params {
    fn default() -> Self {
        let ball_mass = 0.1406;
        let ball_radius = 0.0262;
        let cue_mass = 0.54;
        Params {
            g: 9.81,
            ball_mass,
            ball_radius,
            mu_slide: 0.21,
            mu_roll: 0.0128,
            sidespin_decel: 22.0,
            e_ball: 0.89,
            mu_ball: 0.05,
            e_cushion: 0.98,
            mu_cushion: 0.14,
            cushion_height: 1.4 * ball_radius,
            cue_mass,
            cue_tip_radius: 0.010,
            // Centre hit: V_ball / V_cue = (1 + e_t) m_c / (m_c + M) = 1.45.
            cue_tip_restitution: CENTRE_SPEED_TRANSFER * (cue_mass + ball_mass) / cue_mass - 1.0,
            cue_endmass: squirt_endmass(ball_mass, ball_radius, 0.012, 2.5_f64.to_radians()),
            miscue_limit: 0.5,
            slope_x: 0.0,
            slope_y: 0.0,
            nap_drift: 0.0,
            mu_slide_low: 0.21,
            slide_speed_scale: 0.0,
            e_cushion_falloff: 0.0,
            e_cushion_knee: 1.5,
        }
    }
}

/// The tip end mass that gives a squirt angle `angle` at side offset `b`
/// (inverse of [`crate::cue::squirt_ratio`], solved in closed form).
pub fn squirt_endmass(mass: f64, radius: f64, b: f64, angle: f64) -> f64 {
    let s = b / radius;
    let c2 = 1.0 - s * s;
    // tan(squirt) = 2.5 s cos(a) / (1 + 2.5 cos^2(a) + M/m_e)  =>  solve for m_e.
    let denom = 2.5 * s * c2.sqrt() / angle.tan() - 1.0 - 2.5 * c2;
    mass / denom
}

/// A parameter value that cannot be simulated.
#[derive(Clone, Debug, PartialEq)]
pub struct ParamError {
    /// The parameter's documented name (as in the scene file's `[params]`).
    pub name: &'static str,
    /// Why the value is rejected.
    pub reason: String,
}

impl std::fmt::Display for ParamError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.name, self.reason)
    }
}

impl std::error::Error for ParamError {}

impl Params {
    /// Moment of inertia of a solid ball about a diameter, 2 M R^2 / 5.
    pub fn inertia(&self) -> f64 {
        0.4 * self.ball_mass * self.ball_radius * self.ball_radius
    }

    /// sin(theta), where theta is the angle of the cushion contact normal to the
    /// horizontal: the nose touches the ball at height h, sin(theta) = (h - R) / R (thesis §6.2).
    pub fn cushion_sin_theta(&self) -> f64 {
        (self.cushion_height - self.ball_radius) / self.ball_radius
    }

    /// Horizontal distance from a cushion's nose line to the centre of a ball touching it,
    /// R cos(theta) (0.9165 R for h = 7R/5).
    pub fn cushion_contact_distance(&self) -> f64 {
        let s = self.cushion_sin_theta();
        self.ball_radius * (1.0 - s * s).sqrt()
    }

    /// The cushion's restitution for an impact at normal speed `v`, m/s.
    pub fn e_cushion_at(&self, v: f64) -> f64 {
        (self.e_cushion - self.e_cushion_falloff * (v - self.e_cushion_knee).max(0.0)).max(0.0)
    }

    /// The parameter of this scene-file name, to be set (None for an unknown name).
    pub fn field_mut(&mut self, name: &str) -> Option<&mut f64> {
        Some(match name {
            "g" => &mut self.g,
            "ball_mass" => &mut self.ball_mass,
            "ball_radius" => &mut self.ball_radius,
            "mu_slide" => &mut self.mu_slide,
            "mu_roll" => &mut self.mu_roll,
            "sidespin_decel" => &mut self.sidespin_decel,
            "e_ball" => &mut self.e_ball,
            "mu_ball" => &mut self.mu_ball,
            "e_cushion" => &mut self.e_cushion,
            "mu_cushion" => &mut self.mu_cushion,
            "cushion_height" => &mut self.cushion_height,
            "cue_mass" => &mut self.cue_mass,
            "cue_tip_radius" => &mut self.cue_tip_radius,
            "cue_tip_restitution" => &mut self.cue_tip_restitution,
            "cue_endmass" => &mut self.cue_endmass,
            "miscue_limit" => &mut self.miscue_limit,
            "slope_x" => &mut self.slope_x,
            "slope_y" => &mut self.slope_y,
            "nap_drift" => &mut self.nap_drift,
            "mu_slide_low" => &mut self.mu_slide_low,
            "slide_speed_scale" => &mut self.slide_speed_scale,
            "e_cushion_falloff" => &mut self.e_cushion_falloff,
            "e_cushion_knee" => &mut self.e_cushion_knee,
            _ => return None,
        })
    }

    /// The parameters as (name, value) pairs, with their scene-file names.
    pub fn named(&self) -> [(&'static str, f64); 23] {
        [
            ("g", self.g),
            ("ball_mass", self.ball_mass),
            ("ball_radius", self.ball_radius),
            ("mu_slide", self.mu_slide),
            ("mu_roll", self.mu_roll),
            ("sidespin_decel", self.sidespin_decel),
            ("e_ball", self.e_ball),
            ("mu_ball", self.mu_ball),
            ("e_cushion", self.e_cushion),
            ("mu_cushion", self.mu_cushion),
            ("cushion_height", self.cushion_height),
            ("cue_mass", self.cue_mass),
            ("cue_tip_radius", self.cue_tip_radius),
            ("cue_tip_restitution", self.cue_tip_restitution),
            ("cue_endmass", self.cue_endmass),
            ("miscue_limit", self.miscue_limit),
            ("slope_x", self.slope_x),
            ("slope_y", self.slope_y),
            ("nap_drift", self.nap_drift),
            ("mu_slide_low", self.mu_slide_low),
            ("slide_speed_scale", self.slide_speed_scale),
            ("e_cushion_falloff", self.e_cushion_falloff),
            ("e_cushion_knee", self.e_cushion_knee),
        ]
    }

    /// Checks that every value is finite and physically meaningful.
    pub fn validate(&self) -> Result<(), ParamError> {
        for (name, v) in self.named() {
            if !v.is_finite() {
                return Err(ParamError {
                    name,
                    reason: format!("must be a finite number, got {v}"),
                });
            }
        }
        let positive = [
            ("g", self.g),
            ("ball_mass", self.ball_mass),
            ("ball_radius", self.ball_radius),
            ("cue_mass", self.cue_mass),
        ];
        for (name, v) in positive {
            if v <= 0.0 {
                return Err(ParamError {
                    name,
                    reason: format!("must be > 0, got {v}"),
                });
            }
        }
        let non_negative = [
            ("mu_slide", self.mu_slide),
            ("mu_roll", self.mu_roll),
            ("sidespin_decel", self.sidespin_decel),
            ("mu_ball", self.mu_ball),
            ("mu_cushion", self.mu_cushion),
            ("cue_tip_radius", self.cue_tip_radius),
            // Zero end mass: no squirt.
            ("cue_endmass", self.cue_endmass),
            ("mu_slide_low", self.mu_slide_low),
            ("slide_speed_scale", self.slide_speed_scale),
            ("e_cushion_falloff", self.e_cushion_falloff),
            ("e_cushion_knee", self.e_cushion_knee),
        ];
        for (name, v) in non_negative {
            if v < 0.0 {
                return Err(ParamError {
                    name,
                    reason: format!("must be >= 0, got {v}"),
                });
            }
        }
        let unit = [
            ("e_ball", self.e_ball),
            ("e_cushion", self.e_cushion),
            ("cue_tip_restitution", self.cue_tip_restitution),
        ];
        for (name, v) in unit {
            if !(0.0..=1.0).contains(&v) {
                return Err(ParamError {
                    name,
                    reason: format!("a restitution coefficient must lie in [0, 1], got {v}"),
                });
            }
        }
        let r = self.ball_radius;
        if self.cushion_height <= r || self.cushion_height >= 2.0 * r {
            return Err(ParamError {
                name: "cushion_height",
                reason: format!(
                    "the nose must touch the upper half of the ball: R < h < 2R (R = {r} m), got {} m",
                    self.cushion_height
                ),
            });
        }
        if self.slide_speed_scale > 0.0 && self.mu_slide_low > self.mu_slide {
            return Err(ParamError {
                name: "mu_slide_low",
                reason: format!(
                    "sliding friction at rest cannot exceed mu_slide ({}), got {}",
                    self.mu_slide, self.mu_slide_low
                ),
            });
        }
        // A resting ball must stay at rest: the tilt's pull on a rolling ball (5/7 g slope)
        // must be less than the rolling resistance can hold (mu_roll g).
        let tilt = self.slope_x.hypot(self.slope_y);
        if tilt > 0.0 && 5.0 / 7.0 * tilt >= self.mu_roll {
            return Err(ParamError {
                name: if self.slope_x != 0.0 {
                    "slope_x"
                } else {
                    "slope_y"
                },
                reason: format!(
                    "a tilt of {tilt} rad would roll resting balls away: it must stay below \
                     7/5 mu_roll = {} rad",
                    1.4 * self.mu_roll
                ),
            });
        }
        if !(self.miscue_limit > 0.0 && self.miscue_limit < 1.0) {
            return Err(ParamError {
                name: "miscue_limit",
                reason: format!(
                    "must lie in (0, 1) (a fraction of R), got {}",
                    self.miscue_limit
                ),
            });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_named_parameter_can_be_set_by_name() {
        let p = Params::default();
        for (k, (name, _)) in p.named().iter().enumerate() {
            let mut q = p;
            *q.field_mut(name).unwrap() = 1000.0 + k as f64;
            assert_eq!(q.named()[k].1, 1000.0 + k as f64, "{name}");
            assert_eq!(q.named().iter().filter(|(_, v)| *v >= 1000.0).count(), 1);
        }
        assert!(Params::default().field_mut("mu_slid").is_none());
    }

    #[test]
    fn defaults_are_valid_and_match_the_thesis() {
        let p = Params::default();
        p.validate().unwrap();
        assert_eq!(p.mu_slide, 0.21);
        assert!((p.cushion_contact_distance() / p.ball_radius - 0.9165).abs() < 1e-4);
        // Fitted tip restitution must be a physical value.
        assert!(p.cue_tip_restitution > 0.5 && p.cue_tip_restitution < 1.0);
        // End mass of a few grams, as Shepard and Cross report for real cues.
        assert!(
            p.cue_endmass > 0.002 && p.cue_endmass < 0.02,
            "{}",
            p.cue_endmass
        );
    }

    #[test]
    fn rejects_bad_values() {
        let p = Params {
            e_ball: 1.2,
            ..Params::default()
        };
        assert_eq!(p.validate().unwrap_err().name, "e_ball");
        let p = Params {
            mu_slide: f64::NAN,
            ..Params::default()
        };
        assert_eq!(p.validate().unwrap_err().name, "mu_slide");
    }
}
