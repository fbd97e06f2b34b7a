//! Execution noise: how far the strike played strays from the strike intended. One model for
//! the planner's robustness and the player's strokes: independent zero-mean normal errors in
//! the heading, the elevation, the cue speed and the two tip offsets, with the standard
//! deviations of a [`Noise`] value. [`Noise::STANDARD`] is the computational pool tournaments'
//! standard noise (the FastFiz engine's `GaussianNoise` at magnitude 1.0, Computer Olympiad
//! 2005-2008: aim 0.125°, elevation 0.1°, speed 0.075 m/s, tip offsets 0.5 mm each); noise
//! experiments scale all five together ([`Noise::scaled`]).

use crate::problem::{PlanError, RequestField};
use rand::SeedableRng;
use rand::rngs::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use serde::ser::{Serialize, SerializeMap, Serializer};
use snooker_engine::cue::{Cue, MAX_CUE_SPEED, MAX_ELEVATION};
use snooker_engine::shown::Shown;
use snooker_engine::{BallState, Params};

/// A component of the execution noise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NoiseComponent {
    /// Heading, rad.
    Aim,
    /// Elevation of the cue, rad.
    Elevation,
    /// Cue speed, m/s.
    Speed,
    /// Side offset of the tip, m.
    Side,
    /// Height offset of the tip, m.
    Height,
}

impl NoiseComponent {
    /// All of them, in the order a strike's errors are drawn.
    pub const ALL: [NoiseComponent; 5] = [
        NoiseComponent::Aim,
        NoiseComponent::Elevation,
        NoiseComponent::Speed,
        NoiseComponent::Side,
        NoiseComponent::Height,
    ];

    /// Its name (`aim`, `elevation`, `speed`, `side`, `height`).
    pub fn name(self) -> &'static str {
        match self {
            NoiseComponent::Aim => "aim",
            NoiseComponent::Elevation => "elevation",
            NoiseComponent::Speed => "speed",
            NoiseComponent::Side => "side",
            NoiseComponent::Height => "height",
        }
    }

    /// Its unit.
    pub fn unit(self) -> &'static str {
        match self {
            NoiseComponent::Aim | NoiseComponent::Elevation => "rad",
            NoiseComponent::Speed => "m/s",
            NoiseComponent::Side | NoiseComponent::Height => "m",
        }
    }

    /// The component of that name.
    pub fn from_name(name: &str) -> Option<NoiseComponent> {
        Self::ALL.into_iter().find(|c| c.name() == name)
    }
}

/// Standard deviations of the execution errors (independent, zero-mean, normal).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Noise {
    /// Heading, rad.
    pub aim: f64,
    /// Elevation, rad.
    pub elevation: f64,
    /// Cue speed, m/s.
    pub speed: f64,
    /// Side offset, m.
    pub side: f64,
    /// Height offset, m.
    pub height: f64,
}

/// The errors of one executed strike (executed - intended, before the strike limits apply).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct StrikeErrors {
    /// Heading, rad.
    pub aim: f64,
    /// Elevation, rad.
    pub elevation: f64,
    /// Cue speed, m/s.
    pub speed: f64,
    /// Side offset, m.
    pub side: f64,
    /// Height offset, m.
    pub height: f64,
}

impl Default for Noise {
    /// [`Noise::STANDARD`].
    fn default() -> Noise {
        Noise::STANDARD
    }
}

/// Slowest executed cue speed, m/s: the engine takes speeds above zero only, and a noisy
/// strike below this is played at it (a touch of the ball).
pub const MIN_EXECUTED_SPEED: f64 = 1e-3;

impl Noise {
    /// The computational pool tournaments' standard noise (FastFiz `GaussianNoise` 1.0):
    /// aim 0.125°, elevation 0.1°, speed 0.075 m/s, side and height 0.5 mm.
    pub const STANDARD: Noise = Noise {
        aim: 0.125 * std::f64::consts::PI / 180.0,
        elevation: 0.1 * std::f64::consts::PI / 180.0,
        speed: 0.075,
        side: 0.0005,
        height: 0.0005,
    };

    /// No noise: every strike is played as intended.
    pub const ZERO: Noise = Noise {
        aim: 0.0,
        elevation: 0.0,
        speed: 0.0,
        side: 0.0,
        height: 0.0,
    };

    /// Every standard deviation times `k` (the tournaments' noise experiments).
    pub fn scaled(self, k: f64) -> Noise {
        Noise {
            aim: k * self.aim,
            elevation: k * self.elevation,
            speed: k * self.speed,
            side: k * self.side,
            height: k * self.height,
        }
    }

    /// The standard deviation of component `c`.
    pub fn get(&self, c: NoiseComponent) -> f64 {
        match c {
            NoiseComponent::Aim => self.aim,
            NoiseComponent::Elevation => self.elevation,
            NoiseComponent::Speed => self.speed,
            NoiseComponent::Side => self.side,
            NoiseComponent::Height => self.height,
        }
    }

    /// Sets the standard deviation of component `c`.
    pub fn set(&mut self, c: NoiseComponent, value: f64) {
        match c {
            NoiseComponent::Aim => self.aim = value,
            NoiseComponent::Elevation => self.elevation = value,
            NoiseComponent::Speed => self.speed = value,
            NoiseComponent::Side => self.side = value,
            NoiseComponent::Height => self.height = value,
        }
    }

    /// True when every standard deviation is zero.
    pub fn is_zero(&self) -> bool {
        NoiseComponent::ALL.iter().all(|&c| self.get(c) == 0.0)
    }

    /// Checks every standard deviation: a finite number, at least 0.
    pub fn check(&self) -> Result<(), PlanError> {
        for c in NoiseComponent::ALL {
            let v = self.get(c);
            if !(v.is_finite() && v >= 0.0) {
                return Err(PlanError::BadInput {
                    field: RequestField::Noise(c),
                    reason: format!(
                        "expected a finite number >= 0 ({}), got {}",
                        c.unit(),
                        Shown(v)
                    ),
                });
            }
        }
        Ok(())
    }

    /// One strike's errors drawn from `rng`: five standard normal draws in the order of
    /// [`NoiseComponent::ALL`], each times its standard deviation (always five draws, so a
    /// zero component does not shift the others).
    pub fn draw(&self, rng: &mut ChaCha8Rng) -> StrikeErrors {
        let mut z = [0.0; 5];
        for (k, c) in NoiseComponent::ALL.into_iter().enumerate() {
            let n: f64 = StandardNormal.sample(rng);
            // Finite always: a deviation near f64::MAX times a draw beyond 1 would overflow.
            z[k] = (self.get(c) * n).clamp(-f64::MAX, f64::MAX);
        }
        StrikeErrors {
            aim: z[0],
            elevation: z[1],
            speed: z[2],
            side: z[3],
            height: z[4],
        }
    }

    /// The strike played when `intended` is meant and the errors drawn from `rng` happen
    /// ([`Noise::draw`], then [`execute`]).
    pub fn apply(&self, intended: &Cue, ball: &BallState, p: &Params, rng: &mut ChaCha8Rng) -> Cue {
        execute(intended, &self.draw(rng), ball, p)
    }
}

/// The strike played: `intended` plus `errors`, brought within what the engine can strike
/// (the cue speed at least [`MIN_EXECUTED_SPEED`] and at most its limit, the elevation within
/// 0 to 89°, the heading wrapped into one turn; an offset the tip cannot reach without a
/// miscue is pulled towards the ball's centre until it can: a miscue is not modelled, thesis
/// eq. 7.7 only bounds where the tip may meet the ball). Intended strikes well inside those
/// limits are played exactly as intended plus the errors.
pub fn execute(intended: &Cue, errors: &StrikeErrors, ball: &BallState, p: &Params) -> Cue {
    let mut aim = intended.aim + errors.aim;
    if aim.abs() > std::f64::consts::TAU {
        aim %= std::f64::consts::TAU;
    }
    let mut cue = Cue {
        speed: (intended.speed + errors.speed).clamp(MIN_EXECUTED_SPEED, MAX_CUE_SPEED),
        aim,
        offset: [
            intended.offset[0] + errors.side,
            intended.offset[1] + errors.height,
        ],
        elevation: (intended.elevation + errors.elevation).clamp(0.0, MAX_ELEVATION),
    };
    // Pull the offset in by 1 % steps until the engine strikes it (at most a few dozen steps:
    // the errors are small beside the miscue limit; the centre always strikes).
    let offset_refused =
        |c: &Cue| matches!(snooker_engine::cue::strike(ball, c, p), Err(e) if e.key == "offset");
    for _ in 0..400 {
        if !offset_refused(&cue) {
            return cue;
        }
        cue.offset = [0.99 * cue.offset[0], 0.99 * cue.offset[1]];
    }
    if offset_refused(&cue) {
        // Still refused after 400 steps (to 2 % of the first offset): an error metres beyond
        // the ball, or a tiny miscue limit. The farthest offset along this direction that
        // strikes, by bisection over the distance from the centre (which always strikes) up
        // to the ball's radius, so that any finite noise is played at the limit. (Bisecting a
        // share of the offset instead lost the limit below its resolution, 2^-64 of an error
        // of 1e19 m, and struck the centre.)
        let full = cue.offset;
        let scale = full[0].abs().max(full[1].abs());
        let (x, y) = (full[0] / scale, full[1] / scale);
        let length = x.hypot(y);
        let unit = [x / length, y / length];
        let at = |r: f64| Cue {
            offset: [r * unit[0], r * unit[1]],
            ..cue
        };
        let (mut lo, mut hi) = (0.0, (scale * length).min(p.ball_radius));
        for _ in 0..64 {
            let mid = 0.5 * (lo + hi);
            if offset_refused(&at(mid)) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        cue = at(lo);
    }
    cue
}

/// A generator for one draw of the noise, seeded from a run's seed and the draw's coordinates
/// (stroke, candidate, sample, ...): the same numbers on any machine and any thread count.
pub fn rng_for(seed: u64, coordinates: &[u64]) -> ChaCha8Rng {
    let mut h = mix(seed ^ 0x5eed_5eed_5eed_5eed);
    for &c in coordinates {
        h = mix(h ^ mix(c.wrapping_add(0x9e37_79b9_7f4a_7c15)));
    }
    ChaCha8Rng::seed_from_u64(h)
}

/// splitmix64's finaliser: a bijection of u64 that spreads every input bit.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

impl Serialize for Noise {
    /// The five standard deviations by name; and `offset`, the plan contract's one standard
    /// deviation of the tip offset (formats.md, "Plan"): side's and height's when they are
    /// equal, else their root mean square (the same mean squared offset of the tip,
    /// side^2 + height^2), so the contract's key is always there.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(6))?;
        for c in NoiseComponent::ALL {
            m.serialize_entry(c.name(), &self.get(c))?;
        }
        m.serialize_entry("offset", &self.offset())?;
        m.end()
    }
}

impl Noise {
    /// The one standard deviation of the tip offset the plan contract names (formats.md,
    /// "Plan"), m: side's when side and height are equal, else their root mean square.
    pub fn offset(&self) -> f64 {
        if self.side == self.height {
            self.side
        } else {
            let rms = (0.5 * (self.side * self.side + self.height * self.height)).sqrt();
            // The squares of a side of 1e155 m overflowed, and the key was written null; hypot
            // does not (it is used only there, so that other values keep their bits).
            if rms.is_finite() {
                rms
            } else {
                self.side.hypot(self.height) * std::f64::consts::FRAC_1_SQRT_2
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn standard_is_the_tournaments_noise() {
        let s = Noise::STANDARD;
        assert!((s.aim.to_degrees() - 0.125).abs() < 1e-12);
        assert!((s.elevation.to_degrees() - 0.1).abs() < 1e-12);
        assert_eq!((s.speed, s.side, s.height), (0.075, 0.0005, 0.0005));
        assert_eq!(Noise::default(), s);
        assert!(Noise::ZERO.is_zero() && !s.is_zero());
        assert_eq!(s.scaled(2.0).speed, 0.15);
        for c in NoiseComponent::ALL {
            assert_eq!(NoiseComponent::from_name(c.name()), Some(c));
        }
    }

    #[test]
    fn the_contracts_offset_is_always_written() {
        // formats.md, "Plan": robustness.noise.offset is a contract key; it went missing when
        // side and height differed.
        let json = |n: &Noise| serde_json::to_value(n).unwrap();
        assert_eq!(json(&Noise::STANDARD)["offset"].as_f64(), Some(0.0005));
        let n = Noise {
            side: 0.001,
            ..Noise::STANDARD
        };
        let v = json(&n);
        assert_eq!(v["side"].as_f64(), Some(0.001));
        assert_eq!(v["height"].as_f64(), Some(0.0005));
        let rms = v["offset"].as_f64().unwrap();
        assert!(
            (rms - (0.5f64 * (1e-6 + 2.5e-7)).sqrt()).abs() < 1e-15,
            "{rms}"
        );
    }

    #[test]
    fn zero_noise_plays_the_strike_intended() {
        let p = Params::default();
        let ball = BallState::at_rest(1.0, 0.5, p.ball_radius);
        let cue = Cue {
            speed: 2.0,
            aim: 0.3,
            offset: [0.004, -0.006],
            elevation: 0.02,
        };
        let mut rng = rng_for(1, &[2, 3]);
        assert_eq!(Noise::ZERO.apply(&cue, &ball, &p, &mut rng), cue);
    }

    #[test]
    fn executed_strikes_stay_within_the_engines_limits() {
        let p = Params::default();
        let ball = BallState::at_rest(1.0, 0.5, p.ball_radius);
        let edge = p.miscue_limit * p.ball_radius;
        let cue = Cue {
            speed: 0.01,
            aim: 6.2,
            offset: [edge, edge],
            elevation: 0.0,
        };
        let loud = Noise::STANDARD.scaled(20.0);
        for k in 0..200 {
            let c = loud.apply(&cue, &ball, &p, &mut rng_for(9, &[k]));
            snooker_engine::cue::strike(&ball, &c, &p).unwrap();
        }
    }

    /// Any finite noise is played at the engine's limits, in its direction: before, a side
    /// error of 1e19 m or more struck the exact centre (the bisection over a share of the
    /// offset lost the limit below its resolution), and a deviation near f64::MAX drew an
    /// infinite error whose heading was NaN.
    #[test]
    fn a_huge_noise_strikes_at_the_limits_in_its_direction() {
        let p = Params::default();
        let ball = BallState::at_rest(1.0, 0.5, p.ball_radius);
        let cue = Cue {
            speed: 2.0,
            aim: 0.3,
            offset: [0.0, 0.0],
            elevation: 0.0,
        };
        let edge = p.miscue_limit * p.ball_radius;
        for side in [1e18, 1e19, 1e100, 1e300, f64::MAX] {
            for sign in [1.0, -1.0] {
                let errors = StrikeErrors {
                    aim: 0.0,
                    elevation: 0.0,
                    speed: 0.0,
                    side: sign * side,
                    height: 0.5 * side,
                };
                let c = execute(&cue, &errors, &ball, &p);
                snooker_engine::cue::strike(&ball, &c, &p).unwrap();
                let r = c.offset[0].hypot(c.offset[1]);
                // The miscue limit is the engine's (cue::strike): at least its radius on the
                // level (edge), and the offset as far out as it allows within 1e-9 of it.
                assert!(
                    r >= edge && r < p.ball_radius,
                    "side {side}: offset {:?}",
                    c.offset
                );
                let further = Cue {
                    offset: [c.offset[0] * (1.0 + 1e-9), c.offset[1] * (1.0 + 1e-9)],
                    ..c
                };
                assert!(snooker_engine::cue::strike(&ball, &further, &p).is_err());
                assert_eq!(c.offset[0].signum(), sign, "side {side}");
                assert!((c.offset[1] / c.offset[0] - 0.5 * sign).abs() < 1e-9);
            }
        }
        let huge = Noise {
            aim: f64::MAX,
            elevation: f64::MAX,
            speed: f64::MAX,
            side: f64::MAX,
            height: f64::MAX,
        };
        for k in 0..50 {
            let c = huge.apply(&cue, &ball, &p, &mut rng_for(3, &[k]));
            assert!(c.aim.is_finite() && c.speed.is_finite(), "{c:?}");
            snooker_engine::cue::strike(&ball, &c, &p).unwrap();
        }
        let json = serde_json::to_value(Noise {
            side: 1e155,
            ..Noise::ZERO
        })
        .unwrap();
        let rms = json["offset"].as_f64().unwrap();
        assert!((rms / (1e155 * std::f64::consts::FRAC_1_SQRT_2) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn the_seed_and_coordinates_decide_the_draw() {
        let n = Noise::STANDARD;
        let a = n.draw(&mut rng_for(5, &[1, 2, 3]));
        assert_eq!(a, n.draw(&mut rng_for(5, &[1, 2, 3])));
        assert_ne!(a, n.draw(&mut rng_for(5, &[1, 2, 4])));
        assert_ne!(a, n.draw(&mut rng_for(6, &[1, 2, 3])));
        assert_ne!(a, n.draw(&mut rng_for(5, &[1, 3, 2])));
    }

    #[test]
    fn serialises_the_five_and_the_contracts_offset() {
        let j = serde_json::to_value(Noise::STANDARD).unwrap();
        let keys: Vec<&String> = j.as_object().unwrap().keys().collect();
        assert_eq!(
            keys,
            ["aim", "elevation", "speed", "side", "height", "offset"]
        );
    }
}
