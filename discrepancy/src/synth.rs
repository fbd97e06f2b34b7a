//! Measured-like data with effects hidden in it: a shot simulated under a truth model (the
//! scene's model plus hidden catalogue effects), seen by an overhead camera at a frame rate,
//! with Gaussian position noise and dropped frames (thesis chapter 5: 30-200 frames per
//! second, about 0.5 mm noise). Effects outside the catalogue ([`Uncatalogued`]) can be hidden
//! too, to check the workflow says "unexplained" rather than name a wrong effect.

use crate::catalogue::Effect;
use crate::data::{Model, ShotData, TrackSample};
use crate::error::DiscrepancyError;
use crate::residuals::setup_for;
use rand::RngExt;
use rand::SeedableRng;
use rand::rngs::ChaCha8Rng;
use rand_distr::{Distribution, Normal};
use serde::Serialize;
use snooker_engine::{
    Ball, BallState, Event, EventKind, Motion, Params, Setup, Shot, SimError, SimOptions, simulate,
};

/// Effects outside the catalogue's forms, for testing that the workflow does not mistake
/// them for catalogue effects (issue 25). Each is a physical law the catalogue has no form
/// for; the engine does not have them either, so the shot is simulated in pieces, each
/// piece's parameters set by the law from the state it starts in and the impact ahead of it
/// (a piece ends at a change of motion law, or [`PIECE`] s on).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Uncatalogued {
    /// A ball whose centre of mass is off its centre wobbles sideways once per revolution:
    /// the moving balls are seen displaced across their direction of travel by
    /// `amplitude` sin(s / R), s the distance travelled, m.
    Wobble {
        /// Amplitude, m.
        amplitude: f64,
    },
    /// A cloth whose rolling resistance depends on the direction of travel (a woven cloth
    /// resists differently along and across its weave): mu_roll along x is the model's,
    /// along y `mu_roll_y`, and mu(heading) = mu_x cos^2 + mu_y sin^2 between.
    AnisotropicRolling {
        /// Rolling resistance across the table.
        mu_roll_y: f64,
    },
    /// Ball-ball friction falling with the impact's speed, as measured throw does
    /// (Alciatore, TP A.14: throw is largest for slow cut shots): mu_ball(v) = mu_ball +
    /// (`mu_slow` - mu_ball) exp(-v / 1 m/s), v the approach speed of the centres.
    ThrowFallingWithSpeed {
        /// Ball-ball friction of a very slow impact.
        mu_slow: f64,
    },
    /// Rolling resistance rising with speed (the cloth's deformation hysteresis grows with
    /// the rate of deformation): mu_roll(v) = mu_roll (1 + v / `speed`).
    RollingRisingWithSpeed {
        /// Speed at which the resistance has doubled, m/s.
        speed: f64,
    },
    /// Cushion restitution depending on the angle of incidence (a glancing ball compresses
    /// the rubber less deep than its normal speed alone says): e = e_cushion - `drop`
    /// sin^2(incidence from the normal).
    CushionAngleRestitution {
        /// Fall of the restitution from square-on to glancing.
        drop: f64,
    },
}

/// Longest piece of a shot simulated with one set of parameters under a law that varies
/// along the path, s.
pub const PIECE: f64 = 0.02;

impl Uncatalogued {
    /// The names `snooker synth` accepts for effects outside the catalogue, with what each
    /// takes.
    pub const NAMES: [&'static str; 5] = [
        "wobble",
        "anisotropic_rolling",
        "throw_falling_with_speed",
        "rolling_rising_with_speed",
        "cushion_angle_restitution",
    ];

    /// The effect of this name with its value; None for an unknown name, an error naming
    /// the admissible value for a known name with a bad value.
    pub fn from_name(name: &str, values: &[f64]) -> Option<Result<Uncatalogued, String>> {
        let (range, low, high, make): (&str, f64, f64, fn(f64) -> Uncatalogued) = match name {
            "wobble" => ("one amplitude in [0, 0.05) m", 0.0, 0.05, |amplitude| {
                Uncatalogued::Wobble { amplitude }
            }),
            "anisotropic_rolling" => ("one mu_roll_y in [0, 0.1)", 0.0, 0.1, |mu_roll_y| {
                Uncatalogued::AnisotropicRolling { mu_roll_y }
            }),
            "throw_falling_with_speed" => ("one mu_slow in [0, 0.5)", 0.0, 0.5, |mu_slow| {
                Uncatalogued::ThrowFallingWithSpeed { mu_slow }
            }),
            "rolling_rising_with_speed" => ("one speed in (0, 100) m/s", 1e-9, 100.0, |speed| {
                Uncatalogued::RollingRisingWithSpeed { speed }
            }),
            "cushion_angle_restitution" => ("one drop in [0, 0.5)", 0.0, 0.5, |drop| {
                Uncatalogued::CushionAngleRestitution { drop }
            }),
            _ => return None,
        };
        Some(match values {
            [v] if *v >= low && *v < high => Ok(make(*v)),
            _ => Err(format!("{name} takes {range}")),
        })
    }

    /// The law's name ([`Uncatalogued::NAMES`]) and its value.
    pub fn name_value(&self) -> (&'static str, f64) {
        match *self {
            Uncatalogued::Wobble { amplitude } => ("wobble", amplitude),
            Uncatalogued::AnisotropicRolling { mu_roll_y } => ("anisotropic_rolling", mu_roll_y),
            Uncatalogued::ThrowFallingWithSpeed { mu_slow } => {
                ("throw_falling_with_speed", mu_slow)
            }
            Uncatalogued::RollingRisingWithSpeed { speed } => ("rolling_rising_with_speed", speed),
            Uncatalogued::CushionAngleRestitution { drop } => ("cushion_angle_restitution", drop),
        }
    }

    /// True for the laws that change the motion (simulated in pieces); the wobble only
    /// changes where the camera sees the balls.
    fn changes_motion(&self) -> bool {
        !matches!(self, Uncatalogued::Wobble { .. })
    }

    /// The parameters of a piece of the shot starting at `balls` under `base`, whose first
    /// event under `base` would be `next` (None: no event in the piece).
    fn piece_params(&self, base: &Params, balls: &[Ball], next: Option<&Event>) -> Params {
        let mut p = *base;
        let fastest = balls
            .iter()
            .filter(|b| b.state.motion.in_play())
            .map(|b| b.state.vel)
            .max_by(|a, b| a.norm().total_cmp(&b.norm()));
        match *self {
            Uncatalogued::Wobble { .. } => {}
            Uncatalogued::AnisotropicRolling { mu_roll_y } => {
                if let Some(v) = fastest.filter(|v| v.xy().norm() > 0.0) {
                    let c2 = v.x * v.x / v.xy().norm_squared();
                    p.mu_roll = base.mu_roll * c2 + mu_roll_y * (1.0 - c2);
                }
            }
            Uncatalogued::ThrowFallingWithSpeed { mu_slow } => {
                if let Some(e) = next.filter(|e| e.kind == EventKind::BallBall) {
                    let v = (e.before[0].vel - e.before[1].vel).norm();
                    p.mu_ball = base.mu_ball + (mu_slow - base.mu_ball) * (-v).exp();
                }
            }
            Uncatalogued::RollingRisingWithSpeed { speed } => {
                if let Some(v) = fastest {
                    p.mu_roll = (base.mu_roll * (1.0 + v.norm() / speed)).min(0.1);
                }
            }
            Uncatalogued::CushionAngleRestitution { drop } => {
                if let Some(e) = next.filter(|e| e.kind == EventKind::BallCushion) {
                    let v = e.before[0].vel.xy();
                    let n = e.after[0].vel.xy() - v;
                    if v.norm() > 0.0 && n.norm() > 0.0 {
                        let cos = v.dot(&n).abs() / (v.norm() * n.norm());
                        p.e_cushion = (base.e_cushion - drop * (1.0 - cos * cos)).max(0.0);
                    }
                }
            }
        }
        p
    }
}

/// A shot simulated in pieces: each piece's start time and simulation.
struct Pieces(Vec<(f64, Shot)>);

impl Pieces {
    /// The state of ball `b` at `t`.
    fn state_at(&self, b: usize, t: f64) -> BallState {
        let (t0, sim) = self
            .0
            .iter()
            .rev()
            .find(|(t0, _)| *t0 <= t)
            .unwrap_or(&self.0[0]);
        sim.tracks[b].state_at(t - t0, &sim.params)
    }

    /// When the last ball stops (the last piece's end).
    fn duration(&self) -> f64 {
        self.0.last().map_or(0.0, |(t0, s)| t0 + s.duration)
    }
}

/// Simulates `setup` under the laws in `laws` that change the motion, piece by piece, up to
/// `horizon`.
fn simulate_in_pieces(
    setup: &Setup,
    laws: &[Uncatalogued],
    horizon: f64,
) -> Result<Pieces, SimError> {
    let laws: Vec<&Uncatalogued> = laws.iter().filter(|u| u.changes_motion()).collect();
    let opts = |h: f64| SimOptions {
        horizon: Some(h),
        ..SimOptions::default()
    };
    if laws.is_empty() {
        return Ok(Pieces(vec![(0.0, simulate(setup, &opts(horizon))?)]));
    }
    let mut pieces = Vec::new();
    let mut t0 = 0.0;
    let mut balls = setup.balls.clone();
    // A shot of a few seconds takes a few hundred pieces; the cap only stops a runaway.
    for _ in 0..100_000 {
        let left = horizon - t0;
        let here = Setup {
            balls: balls.clone(),
            ..setup.clone()
        };
        let trial = simulate(&here, &opts(left.min(PIECE)))?;
        let next = trial.events.first();
        let params = laws
            .iter()
            .fold(setup.params, |p, law| law.piece_params(&p, &balls, next));
        let piece = Setup { params, ..here };
        // The piece takes in the next impact and ends at a change of law after it (or PIECE
        // after it): a restart never starts from balls in contact.
        let reach = next.map_or(PIECE, |e| e.t + PIECE).min(left);
        let sim = simulate(&piece, &opts(reach))?;
        let change = sim
            .events
            .iter()
            .find(|e| e.t > 0.0 && matches!(e.kind, EventKind::Transition(_)));
        let end = change.map_or(sim.duration, |e| e.t);
        let moving = sim.tracks.iter().any(|tr| {
            let s = tr.state_at(end, &sim.params);
            s.motion.in_play() && s.motion != Motion::Stationary
        });
        balls = sim.balls_at(end);
        if let Some(e) = change {
            for (&b, s) in e.balls.iter().zip(&e.after) {
                balls[b].state = *s;
            }
        }
        pieces.push((t0, sim));
        t0 += end;
        if !moving || t0 >= horizon || end <= 0.0 {
            break;
        }
    }
    Ok(Pieces(pieces))
}

/// What to hide in the data.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Hidden {
    /// Catalogue effects with their values.
    pub effects: Vec<(Effect, Vec<f64>)>,
    /// Effects outside the catalogue.
    pub uncatalogued: Vec<Uncatalogued>,
}

impl Hidden {
    /// The truth model: `base` with the hidden catalogue effects on.
    pub fn truth(&self, base: &Model) -> Model {
        self.effects.iter().fold(*base, |m, (e, v)| e.apply(&m, v))
    }
}

/// The camera.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Camera {
    /// Frames per second.
    pub fps: f64,
    /// 1-sigma position noise per coordinate, m.
    pub noise: f64,
    /// Chance that a frame is lost.
    pub drop_rate: f64,
    /// Seed of the noise and the frame drops.
    pub seed: u64,
    /// Longest recording, s (the recording otherwise ends 0.5 s after every ball rests).
    pub max_duration: f64,
}

impl Default for Camera {
    fn default() -> Self {
        Camera {
            fps: 100.0,
            noise: 5e-4,
            drop_rate: 0.02,
            seed: 1,
            max_duration: 20.0,
        }
    }
}

/// Checks a camera's settings; the message names the setting.
pub fn check_camera(c: &Camera) -> Result<(), DiscrepancyError> {
    let bad = |setting, range, value| {
        Err(DiscrepancyError::Camera {
            setting,
            range,
            value,
        })
    };
    if !(c.fps.is_finite() && c.fps > 0.0 && c.fps <= 10_000.0) {
        return bad("fps", "in (0, 10000]", c.fps);
    }
    if !(c.noise.is_finite() && c.noise >= 0.0 && c.noise < 0.1) {
        return bad("noise", "in [0, 0.1) m", c.noise);
    }
    if !(0.0..0.9).contains(&c.drop_rate) {
        return bad("drop rate", "in [0, 0.9)", c.drop_rate);
    }
    if !(c.max_duration.is_finite() && c.max_duration > 0.0) {
        return bad("duration", "positive", c.max_duration);
    }
    Ok(())
}

/// Simulates `shot` under `truth` (its fitted quantities at the scene's values) and the
/// laws outside the catalogue, and films it: the shot's duration (s) and the samples.
pub fn film(
    shot: &ShotData,
    truth: &Model,
    uncatalogued: &[Uncatalogued],
    camera: &Camera,
) -> Result<(f64, Vec<TrackSample>), DiscrepancyError> {
    check_camera(camera)?;
    let values = crate::residuals::scene_values(shot);
    let setup = setup_for(shot, truth, &values)?;
    let sim = simulate_in_pieces(&setup, uncatalogued, camera.max_duration).map_err(|error| {
        DiscrepancyError::Simulation {
            shot: shot.name.clone(),
            error,
        }
    })?;
    let end = (sim.duration() + 0.5).min(camera.max_duration);
    let mut rng = ChaCha8Rng::seed_from_u64(camera.seed);
    let normal = Normal::new(0.0, camera.noise).map_err(|_| DiscrepancyError::Camera {
        setting: "noise",
        range: "in [0, 0.1) m",
        value: camera.noise,
    })?;
    let offsets = wobble_offsets(&sim, uncatalogued, end);
    let mut samples = Vec::new();
    let frames = (end * camera.fps).floor() as usize;
    for f in 0..=frames {
        let t = f as f64 / camera.fps;
        if rng.random::<f64>() < camera.drop_rate {
            continue;
        }
        for b in 0..setup.balls.len() {
            let st = sim.state_at(b, t);
            if !st.motion.in_play() {
                continue;
            }
            let extra = offsets(b, t);
            samples.push(TrackSample {
                t,
                ball: b,
                pos: [
                    st.pos.x + extra[0] + normal.sample(&mut rng),
                    st.pos.y + extra[1] + normal.sample(&mut rng),
                ],
            });
        }
    }
    Ok((sim.duration(), samples))
}

/// The displacement the uncatalogued effects add to ball b at time t.
fn wobble_offsets(
    sim: &Pieces,
    uncatalogued: &[Uncatalogued],
    end: f64,
) -> impl Fn(usize, f64) -> [f64; 2] + use<> {
    const DT: f64 = 1e-3;
    let amplitude: f64 = uncatalogued
        .iter()
        .map(|u| match u {
            Uncatalogued::Wobble { amplitude } => *amplitude,
            _ => 0.0,
        })
        .sum();
    let r = sim.0[0].1.params.ball_radius;
    let balls = sim.0[0].1.tracks.len();
    let steps = (end / DT).ceil() as usize + 1;
    // Per ball: distance travelled and heading on a 1 ms grid.
    let table: Vec<Vec<(f64, f64)>> = if amplitude == 0.0 {
        Vec::new()
    } else {
        (0..balls)
            .map(|b| {
                let mut s = 0.0;
                let mut heading = 0.0;
                let mut prev = sim.state_at(b, 0.0).pos;
                (0..steps)
                    .map(|k| {
                        let st = sim.state_at(b, k as f64 * DT);
                        s += (st.pos - prev).xy().norm();
                        prev = st.pos;
                        if st.vel.xy().norm() > 1e-9 {
                            heading = st.vel.y.atan2(st.vel.x);
                        }
                        (s, heading)
                    })
                    .collect()
            })
            .collect()
    };
    move |b: usize, t: f64| {
        if table.is_empty() {
            return [0.0, 0.0];
        }
        let k = ((t / DT).round() as usize).min(steps - 1);
        let (s, h) = table[b][k];
        let side = amplitude * (s / r).sin();
        [-side * h.sin(), side * h.cos()]
    }
}
