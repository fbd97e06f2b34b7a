//! Balls: their kinds (snooker colours) and their mechanical state.

use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

/// A 3-vector of f64 in the table frame (x along the table, y across, z up).
pub type Vec3 = Vector3<f64>;

/// A solid ball's moment of inertia about a diameter over M R^2: I = 2/5 M R^2 (uniform sphere;
/// thesis §2.4.2).
pub const INERTIA_FACTOR: f64 = 0.4;
/// M R^2 / I for a solid ball, the inverse of [`INERTIA_FACTOR`]: 5/2.
pub const INV_INERTIA_FACTOR: f64 = 2.5;
/// A sliding ball's slip (contact-point velocity) changes at this many times the friction's
/// deceleration mu g: 1 from the centre's, M R^2 / I from the spin's (thesis §2.4.2): 7/2.
pub const SLIP_RATE_FACTOR: f64 = 1.0 + INV_INERTIA_FACTOR;
/// A rolling ball's share of the acceleration a force at its centre would give it free,
/// (M R^2 / I) / (1 + M R^2 / I) = 5/7 (the rest spins it; thesis §2.4.2); also the share of a
/// sliding ball's velocity kept when it comes to roll (equal to `5.0 / 7.0` to the bit).
pub const ROLLING_SHARE: f64 = INV_INERTIA_FACTOR / SLIP_RATE_FACTOR;
/// The share of R omega x z (the spin's) in the velocity a sliding ball rolls on with,
/// 1 / (1 + M R^2 / I) = 2/7 (equal to `2.0 / 7.0` to the bit).
pub const ROLLING_SPIN_SHARE: f64 = 1.0 / SLIP_RATE_FACTOR;

/// The phase of a ball's motion; each phase has its own closed-form law (see [`crate::motion`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Motion {
    /// At rest on the cloth, no spin.
    Stationary,
    /// At rest on the cloth but spinning about the vertical.
    Spinning,
    /// On the cloth, the contact point slipping.
    Sliding,
    /// On the cloth, the contact point at rest (v = w x R e_z).
    Rolling,
    /// Off the cloth, in free flight.
    Airborne,
    /// Fallen into a pocket; out of play.
    Pocketed,
    /// Flown over a cushion and off the table; out of play (WPBSA rules: a ball forced off
    /// the table).
    OffTable,
}

impl Motion {
    /// The name used in the JSON result.
    pub fn name(self) -> &'static str {
        match self {
            Motion::Stationary => "stationary",
            Motion::Spinning => "spinning",
            Motion::Sliding => "sliding",
            Motion::Rolling => "rolling",
            Motion::Airborne => "airborne",
            Motion::Pocketed => "pocketed",
            Motion::OffTable => "off_table",
        }
    }

    /// True for the phases in which the ball's centre moves.
    pub fn is_moving(self) -> bool {
        matches!(self, Motion::Sliding | Motion::Rolling | Motion::Airborne)
    }

    /// True once the ball will not change by itself: at rest on the cloth, pocketed or off
    /// the table (a ball spinning on the spot has not stopped).
    pub fn has_stopped(self) -> bool {
        matches!(
            self,
            Motion::Stationary | Motion::Pocketed | Motion::OffTable
        )
    }

    /// True while the ball is on the table (not pocketed, not off the table).
    pub fn in_play(self) -> bool {
        !matches!(self, Motion::Pocketed | Motion::OffTable)
    }
}

/// The mechanical state of one ball at one instant.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BallState {
    /// Centre position, m (z = R on the cloth).
    pub pos: Vec3,
    /// Centre velocity, m/s.
    pub vel: Vec3,
    /// Angular velocity, rad/s, in the table frame.
    pub spin: Vec3,
    /// Which law the ball follows from this state on.
    pub motion: Motion,
}

/// Snooker ball kinds: the colour, which decides nothing physical.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BallKind {
    /// The cue ball.
    Cue,
    /// A red.
    Red,
    /// Yellow (2 points).
    Yellow,
    /// Green (3 points).
    Green,
    /// Brown (4 points).
    Brown,
    /// Blue (5 points).
    Blue,
    /// Pink (6 points).
    Pink,
    /// Black (7 points).
    Black,
    /// Any other ball.
    Other,
}

impl BallKind {
    /// The kind a ball id names: "cue"/"white", "red…", or a colour name.
    pub fn from_id(id: &str) -> BallKind {
        let id = id.to_ascii_lowercase();
        let prefixes = [
            ("cue", BallKind::Cue),
            ("white", BallKind::Cue),
            ("red", BallKind::Red),
            ("yellow", BallKind::Yellow),
            ("green", BallKind::Green),
            ("brown", BallKind::Brown),
            ("blue", BallKind::Blue),
            ("pink", BallKind::Pink),
            ("black", BallKind::Black),
        ];
        prefixes
            .iter()
            .find(|(p, _)| id.starts_with(p))
            .map(|&(_, k)| k)
            .unwrap_or(BallKind::Other)
    }
}

/// One ball of a scene: its name, kind and starting state.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Ball {
    /// Unique name, as in the scene file.
    pub id: String,
    /// Snooker colour.
    pub kind: BallKind,
    /// State at the start of the shot.
    pub state: BallState,
}

impl BallState {
    /// A ball at rest on the cloth at (x, y).
    pub fn at_rest(x: f64, y: f64, radius: f64) -> BallState {
        BallState {
            pos: Vec3::new(x, y, radius),
            vel: Vec3::zeros(),
            spin: Vec3::zeros(),
            motion: Motion::Stationary,
        }
    }

    /// Velocity of the cloth contact point, u = v + w x (-R e_z), horizontal part
    /// (physics.md: u = (vx - R wy, vy + R wx)).
    pub fn slip(&self, radius: f64) -> Vec3 {
        Vec3::new(
            self.vel.x - radius * self.spin.y,
            self.vel.y + radius * self.spin.x,
            0.0,
        )
    }

    /// The state to the bit: position, velocity and spin as IEEE 754 bits, then the motion's
    /// index (for exact comparisons and fingerprints of shots).
    pub fn to_bits(&self) -> [u64; 10] {
        let mut out = [self.motion as u64; 10];
        for (o, v) in out
            .iter_mut()
            .zip(self.pos.iter().chain(&self.vel).chain(&self.spin))
        {
            *o = v.to_bits();
        }
        out
    }

    /// True when every component is finite.
    pub fn is_finite(&self) -> bool {
        self.pos
            .iter()
            .chain(self.vel.iter())
            .chain(self.spin.iter())
            .all(|v| v.is_finite())
    }

    /// Translational plus rotational kinetic energy, J, plus potential energy above the cloth level.
    pub fn energy(&self, mass: f64, inertia: f64, radius: f64, g: f64) -> f64 {
        if !self.motion.in_play() {
            return 0.0;
        }
        0.5 * mass * self.vel.norm_squared()
            + 0.5 * inertia * self.spin.norm_squared()
            + mass * g * (self.pos.z - radius).max(0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_solid_balls_factors_are_the_fractions_to_the_bit() {
        assert_eq!(INV_INERTIA_FACTOR, 1.0 / INERTIA_FACTOR);
        assert_eq!(SLIP_RATE_FACTOR, 3.5);
        assert_eq!(ROLLING_SHARE, 5.0 / 7.0);
        assert_eq!(ROLLING_SPIN_SHARE, 2.0 / 7.0);
    }

    #[test]
    fn kinds_from_ids() {
        assert_eq!(BallKind::from_id("cue"), BallKind::Cue);
        assert_eq!(BallKind::from_id("red7"), BallKind::Red);
        assert_eq!(BallKind::from_id("Black"), BallKind::Black);
        assert_eq!(BallKind::from_id("object"), BallKind::Other);
    }

    #[test]
    fn rolling_has_no_slip() {
        let r = 0.0262;
        let v = Vec3::new(1.0, 0.5, 0.0);
        let s = BallState {
            pos: Vec3::new(0.0, 0.0, r),
            vel: v,
            spin: Vec3::z().cross(&v) / r,
            motion: Motion::Rolling,
        };
        assert!(s.slip(r).norm() < 1e-15);
    }
}
