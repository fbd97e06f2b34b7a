//! The catalogue of physical effects the workflow can switch on: each with its parameters,
//! the range they may take, a one-line physical description and its source. An effect is a
//! value of [`Effect`]; what it does to a model is [`Effect::apply`].

use crate::data::Model;
use serde::{Deserialize, Serialize};
use snooker_engine::params::MAX_TILT_PER_MU_ROLL;
use snooker_engine::{BallBallModel, CushionModel, Params};

/// A physical effect the engine can switch on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Effect {
    /// Rolling resistance of the cloth.
    RollingResistance,
    /// Sliding friction growing with the slip speed.
    SpeedDependentSliding,
    /// The cloth's resistance to sidespin.
    SidespinDecay,
    /// Cushion restitution falling with impact speed.
    CushionSpeedRestitution,
    /// Ball-ball restitution below 1.
    BallRestitution,
    /// Ball-ball friction (throw).
    BallFriction,
    /// Ball-cushion friction.
    CushionFriction,
    /// The cloth's nap pushing balls sideways.
    NapDrift,
    /// A bed that is not level.
    TableSlope,
    /// Cue squirt.
    Squirt,
    /// A cushion that gives way: rubber of finite travel on a damped backing.
    CompliantCushion,
}

/// One parameter of an effect: the engine parameter it sets and its admissible range.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct EffectParam {
    /// The engine parameter's scene-file name.
    pub name: &'static str,
    /// Its unit, as declared with the parameter (`snooker_engine::params::PARAMS`).
    pub unit: &'static str,
    /// Lowest admissible value.
    pub low: f64,
    /// Highest admissible value.
    pub high: f64,
    /// Typical size of a change worth resolving (finite-difference and scaling step).
    pub scale: f64,
}

impl EffectParam {
    /// The parameter `name` fitted within [`low`, `high`] at the resolution `scale`; its unit
    /// is the one declared with it (every name of the catalogue is a parameter's: tested).
    fn new(name: &'static str, low: f64, high: f64, scale: f64) -> Self {
        EffectParam {
            name,
            unit: Params::info(name).map_or("", |i| i.unit),
            low,
            high,
            scale,
        }
    }

    /// The unit as written after a value: " m/s", or nothing for a pure number ("1").
    pub fn unit_suffix(&self) -> String {
        if self.unit == "1" {
            String::new()
        } else {
            format!(" {}", self.unit)
        }
    }
}

impl Effect {
    /// The whole catalogue.
    pub const ALL: [Effect; 11] = [
        Effect::RollingResistance,
        Effect::SpeedDependentSliding,
        Effect::SidespinDecay,
        Effect::CushionSpeedRestitution,
        Effect::BallRestitution,
        Effect::BallFriction,
        Effect::CushionFriction,
        Effect::NapDrift,
        Effect::TableSlope,
        Effect::Squirt,
        Effect::CompliantCushion,
    ];

    /// The catalogue id (formats.md).
    pub fn id(self) -> &'static str {
        match self {
            Effect::RollingResistance => "rolling_resistance",
            Effect::SpeedDependentSliding => "speed_dependent_sliding",
            Effect::SidespinDecay => "sidespin_decay",
            Effect::CushionSpeedRestitution => "cushion_speed_restitution",
            Effect::BallRestitution => "ball_restitution",
            Effect::BallFriction => "ball_friction",
            Effect::CushionFriction => "cushion_friction",
            Effect::NapDrift => "nap_drift",
            Effect::TableSlope => "table_slope",
            Effect::Squirt => "squirt",
            Effect::CompliantCushion => "compliant_cushion",
        }
    }

    /// The effect with this id.
    pub fn from_id(id: &str) -> Option<Effect> {
        Self::ALL.into_iter().find(|e| e.id() == id)
    }

    /// One line of physics: what the effect is.
    pub fn description(self) -> &'static str {
        match self {
            Effect::RollingResistance => {
                "the cloth resists rolling: a rolling ball decelerates at mu_roll g"
            }
            Effect::SpeedDependentSliding => {
                "sliding friction grows with slip speed s: mu(s) = mu_slide - (mu_slide - \
                 mu_slide_low) exp(-s / slide_speed_scale)"
            }
            Effect::SidespinDecay => {
                "the cloth resists spin about the vertical: sidespin falls at sidespin_decel"
            }
            Effect::CushionSpeedRestitution => {
                "the cushion deforms in hard impacts: e(v) = e_cushion - e_cushion_falloff \
                 (v - e_cushion_knee) above the knee"
            }
            Effect::BallRestitution => {
                "ball-ball impacts lose energy: energetic restitution e_ball below 1"
            }
            Effect::BallFriction => {
                "friction between the balls during impact (throw), with the cloth's friction \
                 at the contact, by the thesis's 3D impact model"
            }
            Effect::CushionFriction => {
                "friction between ball and cushion during impact, by the thesis's 3D impact \
                 model"
            }
            Effect::NapDrift => {
                "the cloth's nap pushes a ball travelling along the table sideways: \
                 nap_drift v^x (v^ x z)"
            }
            Effect::TableSlope => {
                "the bed is tilted: gravity pulls balls along g (slope_x, slope_y)"
            }
            Effect::Squirt => {
                "a strike off the centre line sends the ball off the cue's axis, away from the \
                 side struck (cue end mass cue_endmass)"
            }
            Effect::CompliantCushion => {
                "the cushion gives way: its rubber stores a hard impact's work up to M \
                 cushion_bottom_speed^2 / 2 and gives back e_cushion^2 of it, the backing \
                 behind takes the rest and gives back (1 - cushion_backing_damping v)^2"
            }
        }
    }

    /// Where the law comes from.
    pub fn source(self) -> &'static str {
        match self {
            Effect::RollingResistance => "thesis §2.4.2, §5.1.1.1",
            Effect::SpeedDependentSliding => "Witters & Duymelinck 1986, thesis §2.4.2",
            Effect::SidespinDecay => "thesis §5.3",
            Effect::CushionSpeedRestitution => "thesis §5.1.2, §6.2.5",
            Effect::BallRestitution => "thesis §6.1.3",
            Effect::BallFriction => "thesis §6.1",
            Effect::CushionFriction => "thesis §6.2",
            Effect::NapDrift => "Williams 2002, cited in thesis §5.1.1.1",
            Effect::TableSlope => "a level bed is an assumption (thesis §2.4.2)",
            Effect::Squirt => "Shepard 1997, Cross 2008, thesis §2.4.1.3",
            Effect::CompliantCushion => {
                "thesis §5.1.2, §6.2.5; Hunt & Crossley 1975; Stronge 2000 §2.3"
            }
        }
    }

    /// The engine parameters the effect sets, by scene-file name.
    pub fn names(self) -> &'static [&'static str] {
        match self {
            Effect::RollingResistance => &["mu_roll"],
            Effect::SpeedDependentSliding => &["mu_slide_low", "slide_speed_scale"],
            Effect::SidespinDecay => &["sidespin_decel"],
            Effect::CushionSpeedRestitution => &["e_cushion_falloff"],
            Effect::BallRestitution => &["e_ball"],
            Effect::BallFriction => &["mu_ball"],
            Effect::CushionFriction => &["mu_cushion"],
            Effect::NapDrift => &["nap_drift"],
            Effect::TableSlope => &["slope_x", "slope_y"],
            Effect::Squirt => &["cue_endmass"],
            Effect::CompliantCushion => &["cushion_bottom_speed", "cushion_backing_damping"],
        }
    }

    /// The effect's parameters with their ranges under `model` (empty: the effect cannot be
    /// switched on in this model, as a tilt on a cloth without rolling resistance).
    pub fn params(self, model: &Model) -> Vec<EffectParam> {
        let p = &model.params;
        let one = |name, low, high, scale| vec![EffectParam::new(name, low, high, scale)];
        match self {
            Effect::RollingResistance => one("mu_roll", 0.0, 0.1, 1e-4),
            Effect::SpeedDependentSliding => vec![
                // At most the sliding friction it falls from; its floor of 0.01 comes down
                // below a cloth of mu_slide under 0.02, so that the range is never empty.
                EffectParam::new(
                    "mu_slide_low",
                    0.01_f64.min(0.5 * p.mu_slide),
                    p.mu_slide,
                    1e-3,
                ),
                EffectParam::new("slide_speed_scale", 0.01, 5.0, 1e-2),
            ],
            Effect::SidespinDecay => one("sidespin_decel", 0.0, 200.0, 0.1),
            Effect::CushionSpeedRestitution => one("e_cushion_falloff", 0.0, 1.0, 1e-3),
            Effect::BallRestitution => one("e_ball", 0.2, 1.0, 1e-3),
            Effect::BallFriction => one("mu_ball", 0.0, 0.5, 1e-3),
            Effect::CushionFriction => one("mu_cushion", 0.0, 0.8, 1e-3),
            Effect::NapDrift => one("nap_drift", -0.2, 0.2, 1e-4),
            Effect::TableSlope => {
                // Either slope up to 95 % of the steepest tilt in both directions at once.
                let max = 0.95 * MAX_TILT_PER_MU_ROLL * p.mu_roll / std::f64::consts::SQRT_2;
                if max <= 0.0 {
                    return Vec::new();
                }
                ["slope_x", "slope_y"]
                    .into_iter()
                    .map(|name| EffectParam::new(name, -max, max, 1e-5))
                    .collect()
            }
            Effect::Squirt => one("cue_endmass", 0.0, 0.05, 1e-4),
            Effect::CompliantCushion => vec![
                EffectParam::new("cushion_bottom_speed", 0.1, 10.0, 1e-2),
                EffectParam::new("cushion_backing_damping", 0.0, 2.0, 1e-3),
            ],
        }
    }

    /// Starting points for the fit of the effect's parameters: at or next to the values at
    /// which the effect is off, so that a fit starts from the current model's chi2 and can only
    /// improve on it.
    pub fn starts(self, model: &Model) -> Vec<Vec<f64>> {
        match self {
            Effect::SpeedDependentSliding => vec![vec![0.95 * model.params.mu_slide, 0.3]],
            Effect::BallRestitution => vec![vec![1.0]],
            Effect::TableSlope => vec![vec![0.0, 0.0]],
            // The rubber's travel never used up is the rigid cushion; the data's own speeds
            // decide where it bottoms out, so the fit starts from a few travels.
            Effect::CompliantCushion => vec![vec![10.0, 0.05], vec![2.5, 0.05], vec![1.5, 0.1]],
            _ => vec![vec![0.0]],
        }
    }

    /// True when `model` already has the effect.
    pub fn is_on(self, model: &Model) -> bool {
        let p = &model.params;
        match self {
            Effect::RollingResistance => p.mu_roll > 0.0,
            Effect::SpeedDependentSliding => {
                p.slide_speed_scale > 0.0 && p.mu_slide_low != p.mu_slide
            }
            Effect::SidespinDecay => p.sidespin_decel > 0.0,
            Effect::CushionSpeedRestitution => p.e_cushion_falloff > 0.0,
            Effect::BallRestitution => p.e_ball < 1.0,
            Effect::BallFriction => {
                model.models.ball_ball == BallBallModel::Mathavan && p.mu_ball > 0.0
            }
            Effect::CushionFriction => {
                model.models.cushion != CushionModel::Frictionless && p.mu_cushion > 0.0
            }
            Effect::NapDrift => p.nap_drift != 0.0,
            Effect::TableSlope => p.slope_x != 0.0 || p.slope_y != 0.0,
            Effect::Squirt => p.cue_endmass > 0.0,
            Effect::CompliantCushion => model.models.cushion == CushionModel::Compliant,
        }
    }

    /// `model` with the effect switched off (the value [`Effect::is_on`] reads as off).
    pub fn switch_off(self, model: &Model) -> Model {
        let mut m = *model;
        let p = &mut m.params;
        match self {
            Effect::RollingResistance => p.mu_roll = 0.0,
            Effect::SpeedDependentSliding => p.slide_speed_scale = 0.0,
            Effect::SidespinDecay => p.sidespin_decel = 0.0,
            Effect::CushionSpeedRestitution => p.e_cushion_falloff = 0.0,
            Effect::BallRestitution => p.e_ball = 1.0,
            Effect::BallFriction => p.mu_ball = 0.0,
            Effect::CushionFriction => p.mu_cushion = 0.0,
            Effect::NapDrift => p.nap_drift = 0.0,
            Effect::TableSlope => {
                p.slope_x = 0.0;
                p.slope_y = 0.0;
            }
            Effect::Squirt => p.cue_endmass = 0.0,
            Effect::CompliantCushion => m.models.cushion = CushionModel::Mathavan,
        }
        m
    }

    /// `model` with the effect on at `values` (in the order of [`Effect::params`]).
    pub fn apply(self, model: &Model, values: &[f64]) -> Model {
        let mut m = *model;
        for (name, v) in self.names().iter().zip(values) {
            if let Some(slot) = m.params.field_mut(name) {
                *slot = *v;
            }
        }
        // Friction in an impact needs the frictional model (thesis chapter 6).
        match self {
            Effect::BallFriction => m.models.ball_ball = BallBallModel::Mathavan,
            // A compliant cushion is frictional already.
            Effect::CushionFriction if m.models.cushion == CushionModel::Frictionless => {
                m.models.cushion = CushionModel::Mathavan
            }
            Effect::CompliantCushion => m.models.cushion = CushionModel::Compliant,
            _ => {}
        }
        m
    }

    /// The effect's parameter values in `model`.
    pub fn values(self, model: &Model) -> Vec<f64> {
        let named = model.params.named();
        self.names()
            .iter()
            .map(|name| {
                named
                    .iter()
                    .find(|(n, _)| n == name)
                    .map_or(f64::NAN, |e| e.1)
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use snooker_engine::{Models, Params};

    #[test]
    fn every_fit_range_lies_within_the_parameters_declared_range() {
        // A fit never leaves the values the engine accepts (snooker_engine::params::PARAMS),
        // whatever the rolling resistance a tilt's range depends on.
        // Nor is a range ever empty (a cloth of mu_slide 0.005 gave mu_slide_low [0.01, 0.005],
        // and the fit's clamp panicked), and each effect's start lies in its ranges.
        for (mu_roll, mu_slide) in [(0.0128, 0.212), (0.1, 0.212), (0.0128, 0.005), (0.0, 0.0)] {
            let mut m = Model {
                params: Params::default(),
                models: Models::default(),
            };
            m.params.mu_roll = mu_roll;
            m.params.mu_slide = mu_slide;
            for e in Effect::ALL {
                let params = e.params(&m);
                for start in e.starts(&m).iter().filter(|_| !params.is_empty()) {
                    for (p, v) in params.iter().zip(start) {
                        assert!((p.low..=p.high).contains(v), "{}: start {v}", p.name);
                    }
                }
                for p in params {
                    let info = Params::info(p.name).unwrap();
                    assert!(p.low <= p.high, "{}: [{}, {}]", p.name, p.low, p.high);
                    assert!(
                        info.range.contains(p.low) && info.range.contains(p.high),
                        "{}: [{}, {}] outside {}",
                        p.name,
                        p.low,
                        p.high,
                        info.range
                    );
                }
            }
        }
    }

    fn off() -> Model {
        let on = Model {
            params: Params::default(),
            models: Models::default(),
        };
        Effect::ALL.iter().fold(on, |m, e| e.switch_off(&m))
    }

    #[test]
    fn ids_are_unique_and_round_trip() {
        for e in Effect::ALL {
            assert_eq!(Effect::from_id(e.id()), Some(e));
        }
        assert_eq!(Effect::from_id("spin_swerve"), None);
    }

    #[test]
    fn applying_an_effect_switches_it_on_and_sets_its_values() {
        let base = off();
        for e in Effect::ALL {
            assert!(!e.is_on(&base), "{}", e.id());
            let on_model = if e == Effect::TableSlope {
                Effect::RollingResistance.apply(&base, &[0.0128])
            } else {
                base
            };
            let params = e.params(&on_model);
            assert!(!params.is_empty(), "{}", e.id());
            let names: Vec<&str> = params.iter().map(|p| p.name).collect();
            assert_eq!(names, e.names(), "{}", e.id());
            for p in &params {
                // Each is an engine parameter, with its declared unit, fitted inside its range.
                let info = Params::info(p.name).unwrap_or_else(|| panic!("{}", p.name));
                assert_eq!(p.unit, info.unit, "{}", p.name);
                assert!(
                    info.range.contains(p.low) && info.range.contains(p.high),
                    "{}",
                    p.name
                );
            }
            let values: Vec<f64> = params.iter().map(|p| 0.3 * p.low + 0.7 * p.high).collect();
            let m = e.apply(&on_model, &values);
            assert!(e.is_on(&m), "{}", e.id());
            assert_eq!(e.values(&m), values, "{}", e.id());
            assert!(m.params.validate().is_ok(), "{}", e.id());
            assert!(!e.starts(&on_model).is_empty(), "{}", e.id());
            for start in e.starts(&on_model) {
                assert_eq!(start.len(), params.len());
                for (v, p) in start.iter().zip(&params) {
                    assert!(*v >= p.low && *v <= p.high, "{} start {v}", e.id());
                }
            }
        }
    }

    #[test]
    fn no_tilt_can_be_fitted_without_rolling_resistance() {
        assert!(Effect::TableSlope.params(&off()).is_empty());
    }
}
