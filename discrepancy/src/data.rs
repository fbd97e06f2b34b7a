//! Measured data as the workflow sees it: shots, each with the setup it starts from, the
//! tracked centroids, post-event observables, and which initial quantities are unknown.
//! (Reading them from files is the command line's job: `src/measured.rs`.)

use serde::{Deserialize, Serialize};
use snooker_engine::cue::Cue;
use snooker_engine::{BallState, EventKind, Models, Params, Setup};

/// The physics a shot is simulated with: parameters and impact models.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Model {
    /// Physical parameters.
    pub params: Params,
    /// Impact models.
    pub models: Models,
}

/// One tracked centroid: ball `ball` seen at (x, y) at time `t`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct TrackSample {
    /// Time since the shot's start, s.
    pub t: f64,
    /// Index of the ball in the shot's setup.
    pub ball: usize,
    /// Measured centre on the cloth, m.
    pub pos: [f64; 2],
}

/// A quantity measured on one ball at one moment.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// Horizontal speed, m/s.
    Speed,
    /// Direction of horizontal travel from +x, anticlockwise, degrees.
    Heading,
    /// Velocity along x, m/s.
    VelX,
    /// Velocity along y, m/s.
    VelY,
    /// Angular velocity about the vertical, rad/s.
    SpinZ,
}

/// Smallest stated 1-sigma position noise, m: a micrometre, far below any camera's. Residuals
/// are divided by it; a noise of 1e-300 m made them, and every gap and chi-squared, infinite.
pub const MIN_NOISE: f64 = 1e-6;
/// Stated noise at or above which a measurement is not one, m.
pub const MAX_NOISE: f64 = 0.1;
/// Farthest a tracked ball's centre may lie from the table's origin along x or y, m: the
/// snooker table is 3.569 m by 1.778 m; a kilometre bounds any shot on the open cloth.
pub const MAX_TRACK_COORD: f64 = 1e3;
/// Smallest stated 1-sigma of an observable, in the quantity's own unit.
pub const MIN_SIGMA: f64 = 1e-9;

impl Quantity {
    /// Largest magnitude a measured value of the quantity may have, in its unit: a ball's
    /// speed (m/s) at most [`snooker_engine::sim::setup::MAX_BALL_SPEED`], a heading within a
    /// turn either way (degrees), a spin about the vertical of surface speed
    /// [`snooker_engine::sim::setup::MAX_SPIN_SPEED`] on the smallest ball (15 mm): 10^4 rad/s.
    pub fn limit(self) -> f64 {
        use snooker_engine::sim::setup::MAX_BALL_SPEED;
        match self {
            Quantity::Speed | Quantity::VelX | Quantity::VelY => MAX_BALL_SPEED,
            Quantity::Heading => 360.0,
            Quantity::SpinZ => 1e4,
        }
    }

    /// The quantity's unit, as the data file's messages write it.
    pub fn unit(self) -> &'static str {
        match self {
            Quantity::Speed | Quantity::VelX | Quantity::VelY => "m/s",
            Quantity::Heading => "degrees",
            Quantity::SpinZ => "rad/s",
        }
    }

    /// Every quantity with its data-file name.
    pub const ALL: [(Quantity, &'static str); 5] = [
        (Quantity::Speed, "speed"),
        (Quantity::Heading, "heading"),
        (Quantity::VelX, "vel_x"),
        (Quantity::VelY, "vel_y"),
        (Quantity::SpinZ, "spin_z"),
    ];

    /// The data-file name.
    pub fn name(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(q, _)| *q == self)
            .map_or("", |e| e.1)
    }

    /// Simulated less measured, in the quantity's unit; a heading's difference is the turn
    /// between the two, within [-180, 180) degrees (307 degrees measured is -53 simulated).
    pub fn difference(self, simulated: f64, measured: f64) -> f64 {
        let d = simulated - measured;
        match self {
            Quantity::Heading => (d + 180.0).rem_euclid(360.0) - 180.0,
            _ => d,
        }
    }

    /// The quantity's value for a ball state.
    pub fn of(self, s: &BallState) -> f64 {
        match self {
            Quantity::Speed => s.vel.xy().norm(),
            Quantity::Heading => s.vel.y.atan2(s.vel.x).to_degrees(),
            Quantity::VelX => s.vel.x,
            Quantity::VelY => s.vel.y,
            Quantity::SpinZ => s.spin.z,
        }
    }
}

/// When an observable is taken, relative to the `n`-th event of `kind` involving the ball
/// (counted from 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Moment {
    /// Just after the event.
    After {
        /// Event kind.
        kind: EventKind,
        /// Which one, from 1.
        n: usize,
    },
    /// When the ball next rolls after the event (at once if it rolls straight away): the
    /// speeds "once sliding has ended" of the thesis's Table I.
    Rolling {
        /// Event kind.
        kind: EventKind,
        /// Which one, from 1.
        n: usize,
    },
}

impl Moment {
    /// The event this moment refers to.
    pub fn event(self) -> (EventKind, usize) {
        match self {
            Moment::After { kind, n } | Moment::Rolling { kind, n } => (kind, n),
        }
    }
}

impl std::fmt::Display for Moment {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Moment::After { kind, n } => write!(f, "after:{}#{n}", kind.name()),
            Moment::Rolling { kind, n } => write!(f, "rolling:{}#{n}", kind.name()),
        }
    }
}

/// A measured post-event quantity with its 1-sigma uncertainty.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Observable {
    /// Index of the ball in the shot's setup.
    pub ball: usize,
    /// What was measured.
    pub quantity: Quantity,
    /// When.
    pub when: Moment,
    /// Measured value (units of the quantity).
    pub value: f64,
    /// 1-sigma uncertainty (units of the quantity).
    pub sigma: f64,
}

/// An initial quantity the data does not know well, to be fitted along with the model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Nuisance {
    /// A ball's starting position (x, y).
    Pos(usize),
    /// A ball's starting velocity on the cloth (vx, vy).
    Vel(usize),
    /// A ball's starting angular velocity (wx, wy, wz).
    Spin(usize),
    /// The cue's speed.
    StrikeSpeed,
    /// The cue's heading.
    StrikeAim,
    /// The cue tip's offset (side, height).
    StrikeOffset,
    /// The cue's elevation.
    StrikeElevation,
}

impl Nuisance {
    /// How many numbers it holds.
    pub fn len(self) -> usize {
        match self {
            Nuisance::Pos(_) | Nuisance::Vel(_) | Nuisance::StrikeOffset => 2,
            Nuisance::Spin(_) => 3,
            Nuisance::StrikeSpeed | Nuisance::StrikeAim | Nuisance::StrikeElevation => 1,
        }
    }

    /// Always false: every nuisance holds at least one number.
    pub fn is_empty(self) -> bool {
        false
    }

    /// The data-file name (`cue.vel`, `strike.speed`, ...) given the ball ids.
    pub fn name(self, ids: &[String]) -> String {
        let ball = |i: usize| ids.get(i).cloned().unwrap_or_default();
        match self {
            Nuisance::Pos(i) => format!("{}.pos", ball(i)),
            Nuisance::Vel(i) => format!("{}.vel", ball(i)),
            Nuisance::Spin(i) => format!("{}.spin", ball(i)),
            Nuisance::StrikeSpeed => "strike.speed".into(),
            Nuisance::StrikeAim => "strike.aim".into(),
            Nuisance::StrikeOffset => "strike.offset".into(),
            Nuisance::StrikeElevation => "strike.elevation".into(),
        }
    }

    /// The range a value may take in a fit: what a shot can physically have (the fastest
    /// break is about 10 m/s; a ball spinning at 400 rad/s slips at 10 m/s), so that a
    /// quantity the first stage of a fit cannot yet pin down does not run off to infinity.
    pub fn bounds(self) -> Option<(f64, f64)> {
        match self {
            Nuisance::Pos(_) => Some((-1.0, 5.0)),
            Nuisance::Vel(_) => Some((-15.0, 15.0)),
            Nuisance::Spin(_) => Some((-400.0, 400.0)),
            Nuisance::StrikeSpeed => Some((0.0, snooker_engine::cue::MAX_CUE_SPEED)),
            Nuisance::StrikeAim => None,
            Nuisance::StrikeOffset => Some((-0.02, 0.02)),
            Nuisance::StrikeElevation => Some((0.0, snooker_engine::cue::MAX_ELEVATION)),
        }
    }

    /// Typical size of a change worth resolving: the scale of the fit's finite differences
    /// and of its parameter scaling (SI units).
    pub fn scale(self) -> f64 {
        match self {
            Nuisance::Pos(_) => 1e-3,
            Nuisance::Vel(_) => 1e-2,
            Nuisance::Spin(_) => 1.0,
            Nuisance::StrikeSpeed => 1e-2,
            Nuisance::StrikeAim | Nuisance::StrikeElevation => 1e-3,
            Nuisance::StrikeOffset => 1e-4,
        }
    }
}

/// A cue strike that starts a shot.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct MeasuredStrike {
    /// Index of the struck ball.
    pub ball: usize,
    /// The ball's state before the strike.
    pub before: BallState,
    /// The strike.
    pub cue: Cue,
}

/// One measured shot.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ShotData {
    /// Name (for reports).
    pub name: String,
    /// The setup the shot starts from (the strike, if any, applied with the scene's model).
    pub setup: Setup,
    /// The strike, if the shot starts with one: it is replayed with the model being tested
    /// (squirt depends on the cue's end mass).
    pub strike: Option<MeasuredStrike>,
    /// Tracked centroids, in time order.
    pub samples: Vec<TrackSample>,
    /// Post-event quantities.
    pub observables: Vec<Observable>,
    /// Initial quantities to fit.
    pub nuisances: Vec<Nuisance>,
}

impl ShotData {
    /// The ball ids, in setup order.
    pub fn ids(&self) -> Vec<String> {
        self.setup.balls.iter().map(|b| b.id.clone()).collect()
    }

    /// Time of the last sample, s (0 without samples).
    pub fn last_sample(&self) -> f64 {
        self.samples.iter().map(|s| s.t).fold(0.0, f64::max)
    }
}

/// A measurement: one or more shots sharing a model, and the stated camera noise.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Measurement {
    /// The shots.
    pub shots: Vec<ShotData>,
    /// 1-sigma noise of each tracked coordinate, m.
    pub noise: f64,
    /// The model the workflow starts from.
    pub model: Model,
}

/// A measurement the workflow cannot use.
#[derive(Clone, Debug, PartialEq)]
pub enum DataError {
    /// The noise is not a positive number of metres.
    Noise(f64),
    /// No shots.
    NoShots,
    /// Neither tracks nor observables.
    NothingMeasured,
    /// A sample at a time that is not a time, or of a ball the shot does not have.
    SampleBall {
        /// The shot.
        shot: String,
        /// The sample's time, s.
        t: f64,
        /// The ball it names.
        ball: usize,
        /// Balls in the shot.
        balls: usize,
    },
    /// A sample with a position that is not finite or lies beyond [`MAX_TRACK_COORD`].
    SampleNotFinite {
        /// The shot.
        shot: String,
        /// The sample's time, s.
        t: f64,
    },
    /// An observable of a missing ball, or without a value within [`Quantity::limit`] and a
    /// sigma of [`MIN_SIGMA`] or more.
    Observable {
        /// The shot.
        shot: String,
        /// The quantity's name.
        quantity: &'static str,
        /// When it is measured.
        when: Moment,
        /// The ball it names.
        ball: usize,
    },
    /// A fitted quantity of a ball the shot does not have.
    NuisanceBall {
        /// The shot.
        shot: String,
        /// The ball it names.
        ball: usize,
    },
    /// A strike quantity to be fitted in a shot without a strike.
    NuisanceWithoutStrike {
        /// The shot.
        shot: String,
        /// The quantity's name.
        name: String,
    },
    /// A strike of a ball the shot does not have.
    StrikeBall {
        /// The shot.
        shot: String,
        /// The ball it names.
        ball: usize,
    },
}

impl std::fmt::Display for DataError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            DataError::Noise(v) => write!(
                f,
                "noise must be a number of metres in [{MIN_NOISE:e}, {MAX_NOISE}), got {v:e}"
            ),
            DataError::NoShots => write!(f, "the measurement has no shots"),
            DataError::NothingMeasured => {
                write!(f, "the measurement has neither tracks nor observables")
            }
            DataError::SampleBall {
                shot,
                t,
                ball,
                balls,
            } => write!(
                f,
                "shot {shot}: a sample at t = {t} refers to ball {ball} of {balls}"
            ),
            DataError::SampleNotFinite { shot, t } => {
                write!(
                    f,
                    "shot {shot}: a sample at t = {t} is not within {MAX_TRACK_COORD} m of the \
                     table's origin"
                )
            }
            DataError::Observable {
                shot,
                quantity,
                when,
                ball,
            } => write!(
                f,
                "shot {shot}: observable {quantity} {when} of ball {ball} needs a value within its \
                 limit and a sigma of at least {MIN_SIGMA:e}"
            ),
            DataError::NuisanceBall { shot, ball } => {
                write!(f, "shot {shot}: fitted quantity refers to ball {ball}")
            }
            DataError::NuisanceWithoutStrike { shot, name } => write!(
                f,
                "shot {shot}: {name} is to be fitted but the scene has no [cue] strike"
            ),
            DataError::StrikeBall { shot, ball } => {
                write!(f, "shot {shot}: the strike refers to ball {ball}")
            }
        }
    }
}

impl std::error::Error for DataError {}

impl Measurement {
    /// Checks what the workflow relies on: a positive noise, something measured, samples and
    /// observables referring to existing balls with finite values, and strikes and nuisances
    /// that make sense.
    pub fn validate(&self) -> Result<(), DataError> {
        if !(MIN_NOISE..MAX_NOISE).contains(&self.noise) {
            return Err(DataError::Noise(self.noise));
        }
        if self.shots.is_empty() {
            return Err(DataError::NoShots);
        }
        if self
            .shots
            .iter()
            .all(|s| s.samples.is_empty() && s.observables.is_empty())
        {
            return Err(DataError::NothingMeasured);
        }
        for shot in &self.shots {
            let n = shot.setup.balls.len();
            let name = || shot.name.clone();
            for s in &shot.samples {
                if s.ball >= n || !(0.0..=snooker_scene::build::MAX_SIM_TIME).contains(&s.t) {
                    return Err(DataError::SampleBall {
                        shot: name(),
                        t: s.t,
                        ball: s.ball,
                        balls: n,
                    });
                }
                if !s.pos.iter().all(|v| v.abs() <= MAX_TRACK_COORD) {
                    return Err(DataError::SampleNotFinite {
                        shot: name(),
                        t: s.t,
                    });
                }
            }
            for o in &shot.observables {
                if o.ball >= n
                    || !(-o.quantity.limit()..=o.quantity.limit()).contains(&o.value)
                    || !(o.sigma.is_finite() && o.sigma >= MIN_SIGMA)
                {
                    return Err(DataError::Observable {
                        shot: name(),
                        quantity: o.quantity.name(),
                        when: o.when,
                        ball: o.ball,
                    });
                }
            }
            for nu in &shot.nuisances {
                match *nu {
                    Nuisance::Pos(i) | Nuisance::Vel(i) | Nuisance::Spin(i) if i >= n => {
                        return Err(DataError::NuisanceBall {
                            shot: name(),
                            ball: i,
                        });
                    }
                    Nuisance::StrikeSpeed
                    | Nuisance::StrikeAim
                    | Nuisance::StrikeOffset
                    | Nuisance::StrikeElevation
                        if shot.strike.is_none() =>
                    {
                        return Err(DataError::NuisanceWithoutStrike {
                            shot: name(),
                            name: nu.name(&shot.ids()),
                        });
                    }
                    _ => {}
                }
            }
            if let Some(st) = &shot.strike
                && st.ball >= n
            {
                return Err(DataError::StrikeBall {
                    shot: name(),
                    ball: st.ball,
                });
            }
        }
        Ok(())
    }

    /// Number of residuals: two per sample, one per observable.
    pub fn residual_count(&self) -> usize {
        self.shots
            .iter()
            .map(|s| 2 * s.samples.len() + s.observables.len())
            .sum()
    }
}
