//! The player's visit for the page (`snooker play`'s question on a frame): the break-building
//! player of the player crate plays from the frame until it misses or fouls, each stroke
//! chosen under the execution noise, played with the noise drawn for it, and judged by the
//! referee, exactly as the command plays a visit. It runs as a job: each stroke is reported as
//! soon as it is played (the page animates it while the player thinks about the next), the
//! shots simulated so far are the job's progress, and the job's cancellation flag is the
//! player's [`Watch`] (it stops within a batch of shots).
//!
//! Each stroke reported ([`PlayedStroke`]) carries the player's typed [`Decision`] as it was
//! made (the same fields as Python's `choose`: where the cue ball in hand went, the
//! nomination, the strike meant, the stroke planned and the alternatives considered with their
//! values), the strike played, the referee's result, the shot's paths and the frames before
//! and after. Nothing is recomputed or invented for the page.

use crate::body::REQUEST;
use crate::error::ApiError;
use crate::input::{self, FRAME};
use crate::jobs::Job;
use crate::limits::Limits;
use crate::position::{self, Position};
use crate::shot::{self, ShotView};
use serde::{Deserialize, Serialize};
use serde_json::Value;
use snooker_planner::{Noise, StrikeSpec};
use snooker_player::{
    ChooseError, Considered, Decision, End, PlayError, PlayOptions, Player, StrokeRecord, Until,
    Watch, play,
};
use snooker_rules::{Frame, Next};
use snooker_scene::result::ShotRecord;
use std::sync::Arc;

/// The player's effort per stroke when the request does not say (simulated shots): about
/// 0.3 s a decision on 2 idle cores, a few seconds while other work shares them (the command
/// line's default, 4000, takes about 0.7 s idle).
pub const DEFAULT_EFFORT: u64 = 1500;

/// A request for the player's visit.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlayRequest {
    /// The frame (the frame file's keys; its `cue`, if any, is ignored, as `snooker play`
    /// ignores it).
    pub frame: Value,
    /// The search's budget per stroke, simulated shots (default [`DEFAULT_EFFORT`]).
    #[serde(default)]
    pub effort: Option<u64>,
    /// The seed of every random draw (default 1): the same request plays the same visit.
    #[serde(default)]
    pub seed: Option<u64>,
    /// The execution noise: `standard` (the default, [`Noise::STANDARD`]) or `0` (none).
    #[serde(default)]
    pub noise: Option<String>,
    /// Most strokes of the visit (default and most: the server's limit).
    #[serde(default)]
    pub strokes: Option<usize>,
    /// Sample rate of the strokes' paths, Hz.
    #[serde(default)]
    pub rate: Option<f64>,
}

/// The player's decision for a stroke, as Python's `snooker.choose` gives it.
#[derive(Debug, Clone, Serialize)]
pub struct DecisionView {
    /// Where the cue ball in hand was placed (plan, m); null when not in hand.
    pub cue_ball: Option<[f64; 2]>,
    /// The colour nominated (or the free ball), if any.
    pub nominated: Option<&'static str>,
    /// The strike meant.
    pub strike: StrikeSpec,
    /// What the strike was planned as: kind, ball, pocket, pot probability, expected value.
    pub plan: Considered,
    /// The next best strokes considered, best first, with their values.
    pub alternatives: Vec<Considered>,
    /// Shots simulated to decide.
    pub shots_simulated: u64,
}

impl DecisionView {
    /// The view of `d`, for the cue ball `cue_id`.
    pub fn of(d: &Decision, cue_id: &str) -> DecisionView {
        DecisionView {
            cue_ball: d.placement,
            nominated: d.nominated.map(|c| c.name()),
            strike: StrikeSpec::new(cue_id, &d.strike),
            plan: d.plan.clone(),
            alternatives: d.alternatives.clone(),
            shots_simulated: d.shots,
        }
    }
}

/// One stroke of the player, as reported while the visit goes on.
#[derive(Debug, Clone, Serialize)]
pub struct PlayedStroke {
    /// Its number in the visit, from 1.
    pub number: u64,
    /// The player at the table.
    pub player: u8,
    /// The agent that chose it.
    pub agent: &'static str,
    /// What it decided.
    pub decision: DecisionView,
    /// The strike played: the one meant plus the execution noise drawn for it.
    pub executed: StrikeSpec,
    /// The referee's result (formats.md, "Referee result", without `shot`).
    pub referee: Value,
    /// Wall time of the decision, s.
    pub decision_time: f64,
    /// The frame the stroke was played from: the cue ball placed, the nomination made.
    pub before: Position,
    /// The shot played.
    pub shot: ShotView,
    /// The frame after the stroke; null when the frame is over.
    pub next: Option<Position>,
}

/// The answer of a play job once it ends (the strokes themselves are the job's parts).
#[derive(Debug, Clone, Serialize)]
pub struct VisitView {
    /// Strokes played.
    pub strokes: usize,
    /// `visit_over`, `frame_over` or `stroke_cap` (as `snooker play --json` says).
    pub end: &'static str,
    /// The winner, when the frame is over.
    pub winner: Option<u8>,
    /// Points the player scored in the visit.
    pub points: u32,
    /// The scores after the visit.
    pub scores: [u32; 2],
    /// The frame left to play; null when the frame is over.
    pub next: Option<Position>,
    /// The seed played with.
    pub seed: u64,
    /// The effort per stroke.
    pub effort: u64,
    /// The execution noise.
    pub noise: Noise,
    /// Shots simulated to decide, all strokes.
    pub shots_simulated: u64,
}

/// A checked request: the frame and how to play it.
pub struct Checked {
    frame: Frame,
    opts: PlayOptions,
    rate: f64,
    limits: Limits,
}

/// The execution noise named `name`.
fn noise(name: Option<&str>) -> Result<Noise, ApiError> {
    match name.unwrap_or("standard") {
        "standard" => Ok(Noise::STANDARD),
        "0" => Ok(Noise::ZERO),
        other => Err(ApiError::bad(
            REQUEST,
            "noise",
            format!("unknown noise \"{other}\" (standard, 0)"),
        )),
    }
}

/// Checks `req`: the frame as `snooker referee` and `snooker play` read it, the request's own
/// keys against the server's limits.
pub fn check(req: PlayRequest, limits: &Limits) -> Result<Checked, ApiError> {
    let file = input::frame(&req.frame, limits)?;
    let effort = req.effort.unwrap_or(DEFAULT_EFFORT);
    if effort == 0 {
        return Err(ApiError::bad(
            REQUEST,
            "effort",
            "at least 1 simulated shot per stroke",
        ));
    }
    if effort > limits.play_effort {
        return Err(ApiError::bad(
            REQUEST,
            "effort",
            format!(
                "{effort} simulated shots per stroke: the server takes at most {}",
                limits.play_effort
            ),
        ));
    }
    let strokes = req.strokes.unwrap_or(limits.play_strokes);
    if strokes == 0 || strokes > limits.play_strokes {
        return Err(ApiError::bad(
            REQUEST,
            "strokes",
            format!(
                "{strokes} strokes: the server plays 1 to {} in a visit",
                limits.play_strokes
            ),
        ));
    }
    let rate = shot::rate(req.rate, limits)?;
    Ok(Checked {
        frame: file.frame,
        opts: PlayOptions {
            noise: noise(req.noise.as_deref())?,
            seed: req.seed.unwrap_or(1),
            effort,
            until: Until::Visit,
            max_strokes: strokes,
            watch: Watch::default(),
        },
        rate,
        limits: *limits,
    })
}

/// The view of stroke `s`: its decision, the referee's result, the shot and the frames.
pub fn stroke_view(s: &StrokeRecord, rate: f64, limits: &Limits) -> Result<Value, ApiError> {
    let cue_id = s
        .frame
        .cue_index()
        .map_or("cue".to_string(), |i| s.frame.balls()[i].id.clone());
    // The shot's result document needs the scene it was played on: the frame file of the
    // stroke (the frame and the strike played), as `snooker referee` reads a play log's line.
    let file = input::frame_toml(&s.frame.to_toml(Some(&s.executed)), FRAME, limits)?;
    let next = match s.frame.next(&s.verdict) {
        Next::Play(f) => Some(position::of_frame(&f)?),
        Next::Over { .. } => None,
    };
    let view = PlayedStroke {
        number: s.number,
        player: s.player,
        agent: s.agent,
        decision: DecisionView::of(&s.decision, &cue_id),
        executed: StrikeSpec::new(&cue_id, &s.executed),
        referee: serde_json::to_value(s.verdict.report::<ShotRecord>(None))
            .map_err(|e| ApiError::internal(e.to_string()))?,
        decision_time: s.decision_time,
        before: position::of_frame(&s.frame)?,
        shot: shot::view(&file.scene, &s.shot, rate, limits),
        next,
    };
    serde_json::to_value(view).map_err(|e| ApiError::internal(e.to_string()))
}

/// Plays the visit as job `job`: each stroke reported as it is played.
pub fn run(checked: Checked, job: &Job) -> Result<Value, ApiError> {
    let Checked {
        frame,
        mut opts,
        rate,
        limits,
    } = checked;
    opts.watch = Watch::with_cancel(job.cancel.clone());
    job.watch(Arc::new(opts.watch.clone()));
    let side = frame.state().to_play;
    job.set_note(format!("player {side} deciding stroke 1"));
    let mut failed = None;
    let game = play(&frame, [&Player, &Player], &opts, |s| {
        match stroke_view(s, rate, &limits).and_then(|v| job.report(v)) {
            Ok(()) => {}
            Err(e) => {
                failed.get_or_insert(e);
            }
        }
        job.set_note(format!(
            "player {side} played stroke {}; deciding stroke {}",
            s.number,
            s.number + 1
        ));
    });
    if let Some(e) = failed {
        return Err(e);
    }
    let game = match game {
        Ok(g) => g,
        Err(PlayError::Choose {
            source: ChooseError::Cancelled,
            ..
        }) => return Err(ApiError::new(409, REQUEST, "", "cancelled")),
        Err(e) => {
            return Err(ApiError::unfinished(FRAME, e.to_string()));
        }
    };
    let (end, winner) = match game.end {
        End::VisitOver => ("visit_over", None),
        End::FrameOver { winner, .. } => ("frame_over", Some(winner)),
        End::StrokeCap => ("stroke_cap", None),
    };
    let view = VisitView {
        strokes: game.strokes.len(),
        end,
        winner,
        points: game.points(side),
        scores: game
            .strokes
            .last()
            .map_or(frame.state().scores, |s| s.verdict.scores),
        next: game.last.as_ref().map(position::of_frame).transpose()?,
        seed: opts.seed,
        effort: opts.effort,
        noise: opts.noise,
        shots_simulated: game.strokes.iter().map(|s| s.decision.shots).sum(),
    };
    serde_json::to_value(view).map_err(|e| ApiError::internal(e.to_string()))
}
