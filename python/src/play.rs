//! The player from Python (the snooker-player crate): `play` plays a visit or a frame under
//! execution noise and hands back the play log's lines (formats.md, "Play log") as Python
//! values; `choose` is one decision, for an agent that plays strokes itself (the Gymnasium
//! environment's baseline). Both run with the GIL released.

use crate::rules::Frame;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use serde::Serialize;
use snooker_planner::{Cancel, Noise, StrikeSpec};
use snooker_player::{
    Agent, Considered, Context, Greedy, PlayOptions, Player, Until, Watch,
    game::DEFAULT_MAX_STROKES,
};
use std::collections::BTreeMap;

fn agent(name: &str, what: &str) -> PyResult<&'static dyn Agent> {
    match name {
        "player" => Ok(&Player),
        "greedy" => Ok(&Greedy),
        _ => Err(PyValueError::new_err(format!(
            "{what}: \"{name}\" is not an agent (player, greedy)"
        ))),
    }
}

fn positive(v: u64, what: &str) -> PyResult<u64> {
    if v == 0 {
        Err(PyValueError::new_err(format!("{what}: must be at least 1")))
    } else {
        Ok(v)
    }
}

/// A stroke's effort: 1 to [`snooker_player::game::MAX_EFFORT`] simulated shots.
fn effort_of(v: u64) -> PyResult<u64> {
    let max = snooker_player::game::MAX_EFFORT;
    if (1..=max).contains(&v) {
        Ok(v)
    } else {
        Err(PyValueError::new_err(format!(
            "effort: 1 to {max} simulated shots per stroke, got {v}"
        )))
    }
}

/// Plays from `frame` as `snooker play` does: `agent` at the table (and `opponent` for the
/// other side in a frame), every stroke with the execution noise added, judged by the rules,
/// until the visit ends (`visit`) or the frame; the play log's lines as Python values.
#[pyfunction]
#[pyo3(signature = (frame, noise=None, seed=1, effort=snooker_player::game::DEFAULT_EFFORT,
                    visit=true, agent="player", opponent="player",
                    max_strokes=DEFAULT_MAX_STROKES))]
#[allow(clippy::too_many_arguments)]
pub fn play<'py>(
    py: Python<'py>,
    frame: &Frame,
    noise: Option<BTreeMap<String, f64>>,
    seed: u64,
    effort: u64,
    visit: bool,
    agent: &str,
    opponent: &str,
    max_strokes: usize,
) -> PyResult<Bound<'py, PyAny>> {
    let cancel = Cancel::new();
    let opts = PlayOptions {
        noise: crate::noise::from_dict(Noise::STANDARD, noise.unwrap_or_default())?,
        seed,
        effort: effort_of(effort)?,
        until: if visit { Until::Visit } else { Until::Frame },
        max_strokes: positive(max_strokes as u64, "max_strokes")? as usize,
        watch: Watch::with_cancel(cancel.clone()),
    };
    opts.check()
        .map_err(|e| PyValueError::new_err(format!("{}: {}", e.key, e.reason)))?;
    let me = self::agent(agent, "agent")?;
    let other = self::agent(opponent, "opponent")?;
    let frame = frame.0.clone();
    let at = frame.state().to_play as usize;
    let mut agents = [other, other];
    agents[at] = me;
    let lines = crate::interrupt::run(py, &cancel, || {
        snooker_player::play(&frame, agents, &opts, |_| {}).map(|game| {
            game.strokes
                .iter()
                .map(|s| serde_json::to_value(s.log_line()))
                .collect::<Result<Vec<_>, _>>()
        })
    })?
    .map_err(|e| PyRuntimeError::new_err(format!("{}: {e}", frame.name())))?
    .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    crate::to_python(py, &lines)
}

/// One decision as Python gets it.
#[derive(Serialize)]
struct DecisionDoc<'a> {
    cue_ball: Option<[f64; 2]>,
    nominated: Option<&'static str>,
    strike: StrikeSpec,
    plan: &'a Considered,
    alternatives: &'a [Considered],
    shots_simulated: u64,
}

/// The stroke `agent` chooses for `frame` (the `stroke`-th of a run seeded `seed`), expecting
/// the execution noise `noise`: where the cue ball in hand goes, the nomination, the strike
/// and what was planned.
#[pyfunction]
#[pyo3(signature = (frame, noise=None, seed=1, stroke=1,
                    effort=snooker_player::game::DEFAULT_EFFORT, agent="player"))]
pub fn choose<'py>(
    py: Python<'py>,
    frame: &Frame,
    noise: Option<BTreeMap<String, f64>>,
    seed: u64,
    stroke: u64,
    effort: u64,
    agent: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let cancel = Cancel::new();
    let ctx = Context {
        noise: crate::noise::from_dict(Noise::STANDARD, noise.unwrap_or_default())?,
        seed,
        stroke,
        effort: effort_of(effort)?,
        watch: Watch::with_cancel(cancel.clone()),
    };
    let who = self::agent(agent, "agent")?;
    let frame = frame.0.clone();
    let d = crate::interrupt::run(py, &cancel, || who.choose(&frame, &ctx))?
        .map_err(|e| PyValueError::new_err(format!("{}: {e}", frame.name())))?;
    let cue_id = frame
        .cue_index()
        .map_or("cue".to_string(), |i| frame.balls()[i].id.clone());
    let doc = DecisionDoc {
        cue_ball: d.placement,
        nominated: d.nominated.map(|c| c.name()),
        strike: StrikeSpec::new(&cue_id, &d.strike),
        plan: &d.plan,
        alternatives: &d.alternatives,
        shots_simulated: d.shots,
    };
    crate::to_python(py, &doc)
}
