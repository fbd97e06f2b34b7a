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
use snooker_engine::{Shot, SimOptions, simulate};

/// Effects outside the catalogue, for testing that the workflow does not mistake them.
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
}

impl Uncatalogued {
    /// The names `snooker synth --effect` accepts for effects outside the catalogue.
    pub const NAMES: [&'static str; 1] = ["wobble"];

    /// The effect of this name with its value.
    pub fn from_name(name: &str, value: f64) -> Option<Uncatalogued> {
        match name {
            "wobble" => Some(Uncatalogued::Wobble { amplitude: value }),
            _ => None,
        }
    }
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
        return bad("fps", "between 0 and 10000", c.fps);
    }
    if !(c.noise.is_finite() && c.noise >= 0.0 && c.noise < 0.1) {
        return bad("noise", "between 0 and 0.1 m", c.noise);
    }
    if !(0.0..0.9).contains(&c.drop_rate) {
        return bad("drop rate", "between 0 and 0.9", c.drop_rate);
    }
    if !(c.max_duration.is_finite() && c.max_duration > 0.0) {
        return bad("duration", "positive", c.max_duration);
    }
    Ok(())
}

/// Simulates `shot` under `truth` (its fitted quantities at the scene's values) and films it.
pub fn film(
    shot: &ShotData,
    truth: &Model,
    uncatalogued: &[Uncatalogued],
    camera: &Camera,
) -> Result<(Shot, Vec<TrackSample>), DiscrepancyError> {
    check_camera(camera)?;
    let values = crate::residuals::scene_values(shot);
    let setup = setup_for(shot, truth, &values)?;
    let opts = SimOptions {
        horizon: Some(camera.max_duration),
        ..SimOptions::default()
    };
    let sim = simulate(&setup, &opts).map_err(|error| DiscrepancyError::Simulation {
        shot: shot.name.clone(),
        error,
    })?;
    let end = (sim.duration + 0.5).min(camera.max_duration);
    let mut rng = ChaCha8Rng::seed_from_u64(camera.seed);
    let normal = Normal::new(0.0, camera.noise).map_err(|_| DiscrepancyError::Camera {
        setting: "noise",
        range: "between 0 and 0.1 m",
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
        for (b, track) in sim.tracks.iter().enumerate() {
            let st = track.state_at(t, &sim.params);
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
    Ok((sim, samples))
}

/// The displacement the uncatalogued effects add to ball b at time t.
fn wobble_offsets(
    sim: &Shot,
    uncatalogued: &[Uncatalogued],
    end: f64,
) -> impl Fn(usize, f64) -> [f64; 2] + use<> {
    const DT: f64 = 1e-3;
    let amplitude: f64 = uncatalogued
        .iter()
        .map(|u| match u {
            Uncatalogued::Wobble { amplitude } => *amplitude,
        })
        .sum();
    let r = sim.params.ball_radius;
    let steps = (end / DT).ceil() as usize + 1;
    // Per ball: distance travelled and heading on a 1 ms grid.
    let table: Vec<Vec<(f64, f64)>> = if amplitude == 0.0 {
        Vec::new()
    } else {
        sim.tracks
            .iter()
            .map(|track| {
                let mut s = 0.0;
                let mut heading = 0.0;
                let mut prev = track.state_at(0.0, &sim.params).pos;
                (0..steps)
                    .map(|k| {
                        let st = track.state_at(k as f64 * DT, &sim.params);
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
