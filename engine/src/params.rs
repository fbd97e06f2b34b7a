//! Physical parameters, their defaults, units, valid ranges and where each default comes from.
//!
//! All values are SI. Defaults are the thesis's measured or fitted values
//! (Mathavan, "Trajectory solutions for a game-playing robot...", cited as
//! "thesis §x.y"); the few that the thesis does not give are marked as
//! assumptions with their reason. Each parameter is declared once, in `declare_params!`'s
//! call below; the struct, its defaults, the table of [`PARAMS`] (name, unit, range, source),
//! access by name and the range checks are all derived from that one declaration.

use crate::ball::INV_INERTIA_FACTOR;
use crate::shown::Shown;
use serde::{Deserialize, Serialize};

/// The cushion nose's height over the ball radius, h / R = 7/5 (thesis §6.2: the nose touches
/// the ball at h = 7R/5, so the contact normal rises at sin(theta) = 2/5).
pub const NOSE_HEIGHT_PER_RADIUS: f64 = 1.4;

/// Largest [`Params::cushion_jam`] accepted: the cushion's normal impulse must still stop the
/// ball at no more than ten times the frictionless impulse's cost.
pub const MAX_CUSHION_JAM: f64 = 0.9;

/// Thesis §5.1.4: ball speed / cue speed for a centre-ball (stun) strike.
pub const CENTRE_SPEED_TRANSFER: f64 = 1.45;

/// Default ball mass, kg (thesis §6.1.4.2).
const BALL_MASS: f64 = 0.1406;
/// Default ball radius, m (thesis §6.1.4.2).
const BALL_RADIUS: f64 = 0.0262;
/// Default cue mass, kg (a 19 oz cue).
const CUE_MASS: f64 = 0.54;

/// One end of a parameter's valid range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bound {
    /// The value itself is allowed.
    Inclusive(f64),
    /// Values up to (but not including) this one are allowed.
    Exclusive(f64),
}

/// The values a parameter may take: a physical range, documented with its reason.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ValidRange {
    /// Lower end.
    pub lo: Bound,
    /// Upper end.
    pub hi: Bound,
}

impl ValidRange {
    /// [lo, hi].
    pub const fn closed(lo: f64, hi: f64) -> ValidRange {
        ValidRange {
            lo: Bound::Inclusive(lo),
            hi: Bound::Inclusive(hi),
        }
    }

    /// (lo, hi].
    pub const fn above(lo: f64, hi: f64) -> ValidRange {
        ValidRange {
            lo: Bound::Exclusive(lo),
            hi: Bound::Inclusive(hi),
        }
    }

    /// (lo, hi).
    pub const fn open(lo: f64, hi: f64) -> ValidRange {
        ValidRange {
            lo: Bound::Exclusive(lo),
            hi: Bound::Exclusive(hi),
        }
    }

    /// True when `v` lies in the range (false for NaN).
    pub fn contains(&self, v: f64) -> bool {
        let lo = match self.lo {
            Bound::Inclusive(a) => v >= a,
            Bound::Exclusive(a) => v > a,
        };
        let hi = match self.hi {
            Bound::Inclusive(b) => v <= b,
            Bound::Exclusive(b) => v < b,
        };
        lo && hi
    }

    /// The smallest and largest values (the ends, open or not).
    pub fn ends(&self) -> (f64, f64) {
        let v = |b: Bound| match b {
            Bound::Inclusive(x) | Bound::Exclusive(x) => x,
        };
        (v(self.lo), v(self.hi))
    }
}

impl std::fmt::Display for ValidRange {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (open, lo) = match self.lo {
            Bound::Inclusive(a) => ('[', a),
            Bound::Exclusive(a) => ('(', a),
        };
        let (close, hi) = match self.hi {
            Bound::Inclusive(b) => (']', b),
            Bound::Exclusive(b) => (')', b),
        };
        write!(f, "{open}{lo}, {hi}{close}")
    }
}

/// What is known of one parameter: its scene-file name, unit, valid range and source.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParamInfo {
    /// Name in scene files' `[params]`, in `--param NAME=VALUE` and in the JSON result.
    pub name: &'static str,
    /// SI unit ("1" for a pure number).
    pub unit: &'static str,
    /// The values accepted.
    pub range: ValidRange,
    /// Where the default comes from (thesis section, paper, or the assumption made).
    pub source: &'static str,
}

/// Declares every parameter once: its field (with its doc comment), unit, default, valid
/// range and source. Generates [`Params`], its `Default`, [`PARAMS`], and access by name.
macro_rules! declare_params {
    ($(
        $(#[doc = $doc:literal])*
        $name:ident: unit $unit:literal, default $default:expr, range $range:expr,
            source $source:literal;
    )*) => {
        /// Every physical parameter of a shot (see [`PARAMS`] for units, ranges and sources).
        #[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
        pub struct Params {
            $($(#[doc = $doc])* pub $name: f64,)*
        }

        impl Default for Params {
            fn default() -> Self {
                Params { $($name: $default,)* }
            }
        }

        /// Every parameter's name, unit, valid range and source, in declaration order.
        pub const PARAMS: [ParamInfo; declare_params!(@count $($name)*)] = [
            $(ParamInfo {
                name: stringify!($name),
                unit: $unit,
                range: $range,
                source: $source,
            },)*
        ];

        impl Params {
            /// The parameter of this scene-file name, to be set (None for an unknown name).
            pub fn field_mut(&mut self, name: &str) -> Option<&mut f64> {
                match name {
                    $(stringify!($name) => Some(&mut self.$name),)*
                    _ => None,
                }
            }

            /// The parameters as (name, value) pairs, with their scene-file names, in
            /// declaration order.
            pub fn named(&self) -> [(&'static str, f64); PARAMS.len()] {
                [$((stringify!($name), self.$name),)*]
            }
        }
    };
    (@count) => { 0 };
    (@count $head:ident $($tail:ident)*) => { 1 + declare_params!(@count $($tail)*) };
}

declare_params! {
    /// Gravitational acceleration, m/s^2.
    g: unit "m/s^2", default 9.81, range ValidRange::closed(1.0, 25.0),
        source "standard gravity; range: the Moon (1.6) to Jupiter (24.8)";
    /// Ball mass M, kg (thesis §6.1.4.2).
    ball_mass: unit "kg", default BALL_MASS, range ValidRange::closed(0.05, 0.5),
        source "thesis §6.1.4.2";
    /// Ball radius R, m (thesis §6.1.4.2).
    ball_radius: unit "m", default BALL_RADIUS, range ValidRange::closed(0.015, 0.04),
        source "thesis §6.1.4.2; range: below the 90 mm pocket openings (2R <= 80 mm)";
    /// Ball-cloth sliding friction mu_s (thesis §5.1.1.2, mean of 0.178-0.245).
    mu_slide: unit "1", default 0.21, range ValidRange::closed(0.0, 1.0),
        source "thesis §5.1.1.2 (mean of 0.178-0.245)";
    /// Rolling resistance mu_r: deceleration / g while rolling (thesis §5.1.1.1, 0.0127-0.0129).
    mu_roll: unit "1", default 0.0128, range ValidRange::closed(0.0, 0.1),
        source "thesis §5.1.1.1 (0.124-0.126 m/s^2)";
    /// Angular deceleration of sidespin (spin about the vertical), rad/s^2 (thesis §5.3, 21.8 "in the range of 22").
    sidespin_decel: unit "rad/s^2", default 22.0, range ValidRange::closed(0.0, 500.0),
        source "thesis §5.3 (21.8, \"in the range of 22\")";
    /// Ball-ball restitution e (thesis §6.1.4.3, fitted to the head-on data).
    e_ball: unit "1", default 0.89, range ValidRange::closed(0.0, 1.0),
        source "thesis §6.1.4.3";
    /// Ball-ball friction mu_bb (thesis §6.1.4.3).
    mu_ball: unit "1", default 0.05, range ValidRange::closed(0.0, 1.0),
        source "thesis §6.1.4.3";
    /// Ball-cushion restitution e_e (thesis §6.2.5.1).
    e_cushion: unit "1", default 0.98, range ValidRange::closed(0.0, 1.0),
        source "thesis §6.2.5.1";
    /// Ball-cushion friction mu_w (thesis §6.2.5.1).
    mu_cushion: unit "1", default 0.14, range ValidRange::closed(0.0, 1.0),
        source "thesis §6.2.5.1";
    /// Height of the cushion nose above the cloth, m (thesis §6.2: h = 7R/5; AJP paper: 36 mm).
    /// It must touch the upper half of the ball, R < h < 2R; it follows a scene's ball radius
    /// unless given.
    cushion_height: unit "m", default NOSE_HEIGHT_PER_RADIUS * BALL_RADIUS,
        range ValidRange::above(0.0, 0.08), source "thesis §6.2 (7R/5)";
    /// Effective mass of the cue at the tip along its axis, kg. Assumption: a typical
    /// 19 oz (0.54 kg) snooker cue; the arm does not take part in the ~1 ms impact (Cross 2008).
    cue_mass: unit "kg", default CUE_MASS, range ValidRange::closed(0.1, 2.0),
        source "assumption: a 19 oz cue; the arm does not take part in the ~1 ms impact (Cross 2008)";
    /// Cue tip radius, m (thesis §7.1.2: 10 mm).
    cue_tip_radius: unit "m", default 0.010, range ValidRange::closed(0.0, 0.02),
        source "thesis §7.1.2";
    /// Cue tip-ball restitution, fitted so that a centre hit gives the measured
    /// ball/cue speed ratio of 1.45 with `cue_mass` (thesis §5.1.4).
    cue_tip_restitution: unit "1",
        // Centre hit: V_ball / V_cue = (1 + e_t) m_c / (m_c + M) = 1.45.
        default CENTRE_SPEED_TRANSFER * (CUE_MASS + BALL_MASS) / CUE_MASS - 1.0,
        range ValidRange::closed(0.0, 1.0),
        source "fitted: a centre hit gives the measured ball/cue speed ratio 1.45 (thesis §5.1.4)";
    /// Transverse "end mass" of the cue tip, kg, fitted so that a 12 mm side offset gives
    /// the thesis's 2.5 degree squirt (thesis §2.4.1.3; squirt model of Shepard 1997 / Cross 2008).
    cue_endmass: unit "kg",
        default squirt_endmass(BALL_MASS, BALL_RADIUS, 0.012, 2.5_f64.to_radians()),
        range ValidRange::closed(0.0, 0.1),
        source "fitted: 2.5 deg squirt at 12 mm side offset (thesis §2.4.1.3; Shepard 1997, Cross 2008)";
    /// Largest distance of the contact from the line through the ball's centre along the cue
    /// (not the offset cue's own axis), as a fraction of R, before a miscue
    /// (thesis §7.1.2 eq. 7.7, after Alciatore: R/2).
    miscue_limit: unit "1 (fraction of R)", default 0.5, range ValidRange::open(0.0, 1.0),
        source "thesis eq. 7.7 (Alciatore)";
    /// Tilt of the bed along x, rad (a ball feels g slope_x towards +x). Off (0) by default;
    /// the thesis's table is taken as level. See [`crate::motion::cloth`]. Its size, with
    /// `slope_y`'s, must stay below 7/5 `mu_roll` so that resting balls stay put.
    slope_x: unit "rad", default 0.0, range ValidRange::closed(-0.1, 0.1),
        source "level bed assumed (thesis §2.4.2)";
    /// Tilt of the bed along y, rad. Off (0) by default.
    slope_y: unit "rad", default 0.0, range ValidRange::closed(-0.1, 0.1),
        source "level bed assumed (thesis §2.4.2)";
    /// Sideways acceleration of the cloth's nap, m/s^2 ([`crate::motion::cloth::nap`]). Off
    /// (0) by default: the thesis found no nap effect (§5.1.1.1).
    nap_drift: unit "m/s^2", default 0.0, range ValidRange::closed(-0.2, 0.2),
        source "Williams 2002 (thesis §5.1.1.1: not seen in its data)";
    /// Sliding friction at zero slip (Witters and Duymelinck: 0.14); equal to `mu_slide` (no
    /// speed dependence) by default, as the thesis measured none (§5.1.1.2). With a speed
    /// scale it may not exceed `mu_slide`.
    mu_slide_low: unit "1", default 0.21, range ValidRange::closed(0.0, 1.0),
        source "Witters and Duymelinck 1986 (thesis §5.1.1.2: none measured)";
    /// Slip speed over which sliding friction rises from `mu_slide_low` to `mu_slide`, m/s
    /// (0 = no speed dependence, the default).
    slide_speed_scale: unit "m/s", default 0.0, range ValidRange::closed(0.0, 10.0),
        source "Witters and Duymelinck 1986";
    /// Fall of the cushion's restitution with the normal impact speed above
    /// `e_cushion_knee`, per m/s: e_e(v) = e_cushion - e_cushion_falloff (v - knee). Off (0) by
    /// default; the thesis's rigid model holds below about 2.5 m/s (§6.2.5).
    e_cushion_falloff: unit "s/m", default 0.0, range ValidRange::closed(0.0, 1.0),
        source "thesis §5.1.2, §6.2.5";
    /// Normal speed above which the cushion's restitution falls, m/s (thesis §6.2.5.1: e_e
    /// was fitted below 1.5 m/s).
    e_cushion_knee: unit "m/s", default 1.5, range ValidRange::closed(0.0, 30.0),
        source "thesis §6.2.5.1 (e_e fitted below 1.5 m/s)";
    /// The compliant cushion's rubber travel ([`crate::impact::cushion::compliant`]), as the
    /// speed at which a ball carries the energy the rubber stores when its travel is used up:
    /// E_b = M v_b^2 / 2, m/s. Below it the compliant cushion is the rigid one (thesis §6.2,
    /// e_e); above it the ball meets the backing. Used only by `cushion = "compliant"`.
    cushion_bottom_speed: unit "m/s", default 1.853, range ValidRange::closed(0.0, 30.0),
        source "fitted to the thesis's 31 rebounds (§5.1.2, fig. 5.7; docs/discrepancy.md)";
    /// The compliant cushion's backing: Hunt and Crossley's damping alpha, s/m; it gives back
    /// (1 - alpha v)^2 of the energy it takes from a ball meeting it at v. Used only by
    /// `cushion = "compliant"`.
    cushion_backing_damping: unit "s/m", default 0.0692, range ValidRange::closed(0.0, 10.0),
        source "Hunt and Crossley 1975; fitted to the thesis's 31 rebounds (§5.1.2)";
    /// Ball-cloth friction during the cue strike ([`crate::cue::cloth`]): the cloth's friction
    /// percussion under a cue inclined down. Off (0) by default, as the thesis neglects it
    /// (§7.1.3: 2 % of the cue force at 6.5°); `mu_slide`'s 0.21 is the measured cloth.
    mu_strike_cloth: unit "1", default 0.0, range ValidRange::closed(0.0, 1.0),
        source "de la Torre Juarez 1994 (thesis §2.4.1.1; neglected in §7.1.3)";
    /// Ball-bed restitution (the cloth on the slate), Newton's: the share of its downward
    /// speed a ball the bed stops gets back upwards, at a landing and under a cue inclined
    /// down (then the ball jumps: [`crate::motion::bed`]). Off (0) by default: the thesis's
    /// cloth takes a landing's vertical velocity (§6.1.6) and the cue's downward impulse
    /// (§7.1.3). At most 0.9, so that a ball's bounces die out in a few dozen.
    e_bed: unit "1", default 0.0, range ValidRange::closed(0.0, 0.9),
        source "Newton's restitution on the bed (thesis §6.1.6 and §7.1.3 take 0: no bounce)";
}

/// The tip end mass that gives a squirt angle `angle` at side offset `b`
/// (inverse of [`crate::cue::squirt_ratio`], solved in closed form).
pub fn squirt_endmass(mass: f64, radius: f64, b: f64, angle: f64) -> f64 {
    let s = b / radius;
    let c2 = 1.0 - s * s;
    // tan(squirt) = 2.5 s cos(a) / (1 + 2.5 cos^2(a) + M/m_e)  =>  solve for m_e.
    let denom = INV_INERTIA_FACTOR * s * c2.sqrt() / angle.tan() - 1.0 - INV_INERTIA_FACTOR * c2;
    mass / denom
}

/// The steepest tilt of the bed, rad, per unit of `mu_roll`, on which a ball at rest stays at
/// rest: a rolling ball is pulled down the slope by 5/7 g tilt ([`crate::ball::ROLLING_SHARE`];
/// [`crate::motion::cloth`]), which rolling resistance, mu_roll g, must hold: tilt < 7/5 mu_roll.
pub const MAX_TILT_PER_MU_ROLL: f64 = 7.0 / 5.0;

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
        crate::ball::INERTIA_FACTOR * self.ball_mass * self.ball_radius * self.ball_radius
    }

    /// The bed's tilt, rad: the size of (`slope_x`, `slope_y`).
    pub fn tilt(&self) -> f64 {
        self.slope_x.hypot(self.slope_y)
    }

    /// The tilt, rad, below which a ball at rest stays at rest:
    /// [`MAX_TILT_PER_MU_ROLL`] `mu_roll`.
    pub fn max_tilt(&self) -> f64 {
        MAX_TILT_PER_MU_ROLL * self.mu_roll
    }

    /// True when the bed is tilted too steeply for its rolling resistance to hold a ball at
    /// rest ([`MAX_TILT_PER_MU_ROLL`]); [`Params::validate`] rejects such a bed.
    pub fn tilt_rolls_resting_balls(&self) -> bool {
        let tilt = self.tilt();
        tilt > 0.0 && crate::ball::ROLLING_SHARE * tilt >= self.mu_roll
    }

    /// What is known of the parameter named `name` (None for an unknown name).
    pub fn info(name: &str) -> Option<&'static ParamInfo> {
        PARAMS.iter().find(|i| i.name == name)
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

    /// How far the cushion's frictions can push back against the normal impulse of a ball on
    /// the cloth, as a fraction of it: mu_w tan(theta) + mu_s (tan(theta) + mu_w). The thesis's
    /// cushion equations (§6.2, dz = 0) give M dv_y/dP_I = -cos(theta) + mu_w sin(Phi)
    /// sin(theta) - mu_s sin(Phi') (sin(theta) + mu_w sin(Phi) cos(theta)); at its worst the
    /// approach falls at cos(theta) (1 - this) per unit impulse, and not at all when this
    /// reaches 1: the rigid contact jams (the Painlevé paradox of Coulomb friction; Stronge,
    /// *Impact Mechanics*, 2000). The thesis's values give 0.18.
    pub fn cushion_jam(&self) -> f64 {
        let s = self.cushion_sin_theta();
        let tan = s / (1.0 - s * s).sqrt();
        self.mu_cushion * tan + self.mu_slide.max(self.mu_slide_low) * (tan + self.mu_cushion)
    }

    /// The compliant cushion's backing behind its rubber (thesis §6.2.5: the rigid model holds
    /// below about 2.5 m/s, the cushion deforming above).
    pub fn cushion_backing(&self) -> crate::impact::impulse::Backing {
        crate::impact::impulse::Backing {
            bottom_energy: 0.5 * self.ball_mass * self.cushion_bottom_speed.powi(2),
            damping: self.cushion_backing_damping,
        }
    }

    /// The cushion's restitution for an impact at normal speed `v`, m/s.
    pub fn e_cushion_at(&self, v: f64) -> f64 {
        (self.e_cushion - self.e_cushion_falloff * (v - self.e_cushion_knee).max(0.0)).max(0.0)
    }

    /// Checks that every value is finite and within its declared range ([`PARAMS`]), and the
    /// conditions between parameters: the nose on the ball's upper half, sliding friction at
    /// rest not above `mu_slide`, a tilt that leaves resting balls at rest.
    pub fn validate(&self) -> Result<(), ParamError> {
        for ((name, v), info) in self.named().into_iter().zip(PARAMS.iter()) {
            if !v.is_finite() {
                return Err(ParamError {
                    name,
                    reason: format!("must be a finite number, got {v}"),
                });
            }
            if !info.range.contains(v) {
                let unit = if info.unit.starts_with('1') {
                    String::new()
                } else {
                    format!(" {}", info.unit)
                };
                return Err(ParamError {
                    name,
                    reason: format!("must lie in {}{unit}, got {}", info.range, Shown(v)),
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
        let jam = self.cushion_jam();
        if jam > MAX_CUSHION_JAM {
            return Err(ParamError {
                name: "mu_cushion",
                reason: format!(
                    "with mu_cushion = {}, mu_slide = {} and the nose at {} m the cushion's \
                     frictions would wedge a ball under the nose: mu_w tan(theta) + mu_s (tan(theta) \
                     + mu_w) = {jam:.3} must stay below {MAX_CUSHION_JAM} for the rigid cushion \
                     impact to stop the ball (thesis §6.2)",
                    self.mu_cushion, self.mu_slide, self.cushion_height
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
        if self.tilt_rolls_resting_balls() {
            let tilt = self.tilt();
            return Err(ParamError {
                name: if self.slope_x != 0.0 {
                    "slope_x"
                } else {
                    "slope_y"
                },
                reason: format!(
                    "a tilt of {tilt} rad would roll resting balls away: it must stay below \
                     7/5 mu_roll = {} rad",
                    self.max_tilt()
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
    fn the_steepest_tilt_is_where_the_pull_meets_rolling_resistance() {
        assert!((MAX_TILT_PER_MU_ROLL * crate::ball::ROLLING_SHARE - 1.0).abs() < 1e-15);
        let p = Params::default();
        let tilted = |share: f64| Params {
            slope_x: 0.6 * share * p.max_tilt(),
            slope_y: -0.8 * share * p.max_tilt(),
            ..p
        };
        assert!(!tilted(0.999).tilt_rolls_resting_balls());
        tilted(0.999).validate().unwrap();
        assert!(tilted(1.001).tilt_rolls_resting_balls());
        let e = tilted(1.001).validate().unwrap_err();
        assert_eq!(e.name, "slope_x");
        assert!(e.reason.contains("roll resting balls away"), "{e}");
        // Without rolling resistance any tilt rolls a ball away; a level bed none.
        let frictionless = Params {
            mu_roll: 0.0,
            ..tilted(0.5)
        };
        assert!(frictionless.tilt_rolls_resting_balls());
        assert!(!Params { mu_roll: 0.0, ..p }.tilt_rolls_resting_balls());
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
    fn every_range_is_enforced_by_name() {
        // One declaration gives every parameter a range; each end is enforced, naming the
        // parameter (cross-parameter conditions aside).
        let p = Params::default();
        for info in PARAMS {
            assert!(
                info.range.contains(
                    *p.named()
                        .iter()
                        .find(|(n, _)| *n == info.name)
                        .map(|(_, v)| v)
                        .unwrap()
                ),
                "{}",
                info.name
            );
            let (lo, hi) = info.range.ends();
            for bad in [
                lo - 1e-9 * lo.abs().max(1.0),
                hi + 1e-9 * hi.abs().max(1.0),
                1e308,
                -1e308,
            ] {
                let mut q = p;
                *q.field_mut(info.name).unwrap() = bad;
                let e = q.validate().unwrap_err();
                assert_eq!(e.name, info.name, "{bad}: {e}");
            }
            assert!(!info.source.is_empty() && !info.unit.is_empty());
        }
    }

    #[test]
    fn frictions_that_would_jam_the_cushion_are_rejected() {
        let p = Params::default();
        assert!(
            (p.cushion_jam() - 0.182).abs() < 1e-3,
            "{}",
            p.cushion_jam()
        );
        let jammed = Params {
            mu_cushion: 1.0,
            mu_slide: 0.888,
            ..p
        };
        assert_eq!(jammed.validate().unwrap_err().name, "mu_cushion");
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
