//! From a model and the fitted initial quantities to simulated shots, and from simulated
//! shots to residuals: measured minus simulated, in units of the stated uncertainty.

use crate::data::{Measurement, Model, Moment, Nuisance, Observable, ShotData};
use crate::error::DiscrepancyError;
use nalgebra::DMatrix;
use snooker_engine::cue;
use snooker_engine::{BallState, EventKind, Motion, Setup, Shot, SimOptions, Vec3, simulate};

/// How long an observables-only shot is simulated at most, s: long enough for any shot on a
/// full-size table to end, short enough that a model without rolling resistance (in which a
/// ball bounces between the cushions for ever) still returns.
pub const OBSERVABLE_HORIZON: f64 = 30.0;

/// A shot's fitted initial quantities, one value vector per nuisance (in the shot's order).
pub type NuisanceValues = Vec<Vec<f64>>;

/// The values of `shot`'s nuisances as the scene gives them.
pub fn scene_values(shot: &ShotData) -> NuisanceValues {
    shot.nuisances
        .iter()
        .map(|n| {
            let ball = |i: usize| &shot.setup.balls[i].state;
            let cue = shot.strike.map(|s| s.cue);
            match *n {
                Nuisance::Pos(i) => vec![ball(i).pos.x, ball(i).pos.y],
                Nuisance::Vel(i) => vec![ball(i).vel.x, ball(i).vel.y],
                Nuisance::Spin(i) => ball(i).spin.iter().copied().collect(),
                Nuisance::StrikeSpeed => vec![cue.map_or(0.0, |c| c.speed)],
                Nuisance::StrikeAim => vec![cue.map_or(0.0, |c| c.aim)],
                Nuisance::StrikeOffset => cue.map_or(vec![0.0, 0.0], |c| c.offset.to_vec()),
                Nuisance::StrikeElevation => vec![cue.map_or(0.0, |c| c.elevation)],
            }
        })
        .collect()
}

/// Starting values for `shot`'s nuisances: the scene's, except that a fitted starting velocity
/// is estimated from the track itself (a quadratic through the ball's first 8 samples within
/// 0.1 s), as an experimenter would, when the track allows it.
pub fn starting_values(shot: &ShotData) -> NuisanceValues {
    let mut values = scene_values(shot);
    for (n, v) in shot.nuisances.iter().zip(values.iter_mut()) {
        if let Nuisance::Vel(i) = *n
            && let Some(est) = early_velocity(shot, i)
        {
            *v = est.to_vec();
        }
    }
    values
}

/// Velocity at t = 0 from a least-squares quadratic through the ball's first samples.
fn early_velocity(shot: &ShotData, ball: usize) -> Option<[f64; 2]> {
    let pts: Vec<_> = shot
        .samples
        .iter()
        .filter(|s| s.ball == ball && s.t <= 0.1)
        .take(8)
        .collect();
    if pts.len() < 5 {
        return None;
    }
    // Least squares for y = c0 + c1 t + c2 t^2, both coordinates at once.
    let basis = DMatrix::from_fn(pts.len(), 3, |r, c| pts[r].t.powi(c as i32));
    let ys = DMatrix::from_fn(pts.len(), 2, |r, c| pts[r].pos[c]);
    let coef = basis.svd(true, true).solve(&ys, 1e-12).ok()?;
    Some([coef[(1, 0)], coef[(1, 1)]])
}

/// The setup `shot` starts from under `model` with its nuisances at `values`: the strike is
/// replayed with the model's cue parameters, then fitted positions, velocities and spins are
/// put in place.
pub fn setup_for(
    shot: &ShotData,
    model: &Model,
    values: &[Vec<f64>],
) -> Result<Setup, DiscrepancyError> {
    let mut setup = shot.setup.clone();
    setup.params = model.params;
    setup.models = model.models;
    if let Some(st) = shot.strike {
        let mut c = st.cue;
        for (n, v) in shot.nuisances.iter().zip(values) {
            match n {
                Nuisance::StrikeSpeed => c.speed = v[0],
                Nuisance::StrikeAim => c.aim = v[0],
                Nuisance::StrikeOffset => c.offset = [v[0], v[1]],
                Nuisance::StrikeElevation => c.elevation = v[0],
                _ => {}
            }
        }
        let s = cue::strike(&st.before, &c, &model.params).map_err(|error| {
            DiscrepancyError::Strike {
                shot: shot.name.clone(),
                error,
            }
        })?;
        setup.balls[st.ball].state = s.state;
    }
    for (n, v) in shot.nuisances.iter().zip(values) {
        match *n {
            Nuisance::Pos(i) => {
                let s = &mut setup.balls[i].state;
                s.pos.x = v[0];
                s.pos.y = v[1];
            }
            Nuisance::Vel(i) => {
                let s = &mut setup.balls[i].state;
                s.vel = Vec3::new(v[0], v[1], s.vel.z);
                s.motion = Motion::Sliding;
            }
            Nuisance::Spin(i) => {
                let s = &mut setup.balls[i].state;
                s.spin = Vec3::new(v[0], v[1], v[2]);
                s.motion = Motion::Sliding;
            }
            _ => {}
        }
    }
    Ok(setup)
}

/// How far `shot` is simulated: just past its last sample, or long enough for its
/// observables.
pub fn horizon(shot: &ShotData) -> f64 {
    let last = shot.last_sample() + 1e-3;
    if shot.observables.is_empty() {
        last
    } else {
        last.max(OBSERVABLE_HORIZON)
    }
}

/// Simulates `shot` under `model` with its nuisances at `values`, up to the samples within
/// `window` seconds (all of them with `f64::INFINITY`) and its observables.
pub fn simulate_shot(
    shot: &ShotData,
    model: &Model,
    values: &[Vec<f64>],
    window: f64,
) -> Result<Shot, DiscrepancyError> {
    let setup = setup_for(shot, model, values)?;
    let mut end = horizon(shot);
    if shot.observables.is_empty() {
        end = end.min(window + 1e-3);
    }
    let opts = SimOptions {
        horizon: Some(end),
        ..SimOptions::default()
    };
    simulate(&setup, &opts).map_err(|error| DiscrepancyError::Simulation {
        shot: shot.name.clone(),
        error,
    })
}

/// The ball's state at an observable's moment, if the simulated shot has that moment.
pub fn observed_state(sim: &Shot, o: &Observable) -> Option<BallState> {
    let (kind, n) = o.when.event();
    let mut involving = sim
        .events
        .iter()
        .enumerate()
        .filter(|(_, e)| e.balls.contains(&o.ball));
    let (k, e) = involving
        .clone()
        .filter(|(_, e)| e.kind == kind)
        .nth(n.checked_sub(1)?)?;
    let after = |e: &snooker_engine::Event| {
        e.balls
            .iter()
            .position(|&b| b == o.ball)
            .map(|i| e.after[i])
    };
    match o.when {
        Moment::After { .. } => after(e),
        Moment::Rolling { .. } => {
            let first = after(e)?;
            if first.motion == Motion::Rolling {
                return Some(first);
            }
            involving
                .find(|(j, e)| *j > k && after(e).is_some_and(|s| s.motion == Motion::Rolling))
                .and_then(|(_, e)| after(e))
        }
    }
}

/// The simulated value of an observable (None when the moment never comes).
pub fn observed_value(sim: &Shot, o: &Observable) -> Option<f64> {
    observed_state(sim, o).map(|s| o.quantity.of(&s))
}

/// Appends `shot`'s residuals against `sim` to `out`: (simulated - measured) / sigma, x then y
/// for every sample (0 for samples after `window`), then one per observable (an observable
/// whose moment never comes counts as simulated 0).
pub fn residuals(shot: &ShotData, sim: &Shot, noise: f64, window: f64, out: &mut Vec<f64>) {
    let p = &sim.params;
    for s in &shot.samples {
        if s.t > window {
            out.extend([0.0, 0.0]);
            continue;
        }
        let st = sim.tracks[s.ball].state_at(s.t, p);
        out.push((st.pos.x - s.pos[0]) / noise);
        out.push((st.pos.y - s.pos[1]) / noise);
    }
    for o in &shot.observables {
        let v = observed_value(sim, o).unwrap_or(0.0);
        out.push(o.quantity.difference(v, o.value) / o.sigma);
    }
}

/// Every shot of `m` simulated under `model` with nuisances `values` (one vector per shot),
/// for the samples within `window`.
pub fn simulate_all(
    m: &Measurement,
    model: &Model,
    values: &[NuisanceValues],
    window: f64,
) -> Result<Vec<Shot>, DiscrepancyError> {
    m.shots
        .iter()
        .zip(values)
        .map(|(shot, v)| simulate_shot(shot, model, v, window))
        .collect()
}

/// All residuals of `m` against its simulated shots, for the samples within `window`.
pub fn all_residuals(m: &Measurement, sims: &[Shot], window: f64) -> Vec<f64> {
    let mut out = Vec::with_capacity(m.residual_count());
    for (shot, sim) in m.shots.iter().zip(sims) {
        residuals(shot, sim, m.noise, window, &mut out);
    }
    out
}

/// Gap between measured and simulated positions over all samples, m.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct Gap {
    /// Root mean square of the distances.
    pub rms: f64,
    /// Largest distance.
    pub max: f64,
    /// How many samples (or observables) it is over: with none, `rms` and `max` are 0 and say
    /// nothing of the fit.
    pub samples: usize,
}

/// The position gap of `m` against its simulated shots (zero over zero samples without any).
pub fn position_gap(m: &Measurement, sims: &[Shot]) -> Gap {
    let (mut sum, mut max, mut n) = (0.0, 0.0f64, 0usize);
    for (shot, sim) in m.shots.iter().zip(sims) {
        for s in &shot.samples {
            let st = sim.tracks[s.ball].state_at(s.t, &sim.params);
            let d = (st.pos.x - s.pos[0]).hypot(st.pos.y - s.pos[1]);
            sum += d * d;
            max = max.max(d);
            n += 1;
        }
    }
    Gap {
        rms: if n > 0 { (sum / n as f64).sqrt() } else { 0.0 },
        max,
        samples: n,
    }
}

/// The kind of event an observable refers to, for grouping.
pub fn observable_kind(o: &Observable) -> EventKind {
    o.when.event().0
}
