//! Playing on: stroke after stroke, each chosen by the agent at the table, played with the
//! execution noise added, judged by the referee, until the visit or the frame ends.

use crate::agent::{Agent, ChooseError, Context};
use crate::decision::Decision;
use crate::watch::Watch;
use snooker_engine::{Cue, Shot};
use snooker_planner::{Noise, rng_for};
use snooker_rules::{Frame, Next, Player as Side, Verdict};
use std::time::Instant;

/// The default effort: simulated shots per stroke.
pub const DEFAULT_EFFORT: u64 = 4000;
/// The default stroke cap of a frame.
pub const DEFAULT_MAX_STROKES: usize = 300;
/// Most effort a stroke may be given, simulated shots: minutes a stroke on two cores; a
/// count past this is a typo (u64::MAX asked a safety's samples of more memory than exists).
pub const MAX_EFFORT: u64 = 10_000_000;

/// An option of [`PlayOptions`] out of its range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{key}: {reason}")]
pub struct OptionsError {
    /// The option: `effort`, `max_strokes` or `noise.COMPONENT`.
    pub key: String,
    /// Why.
    pub reason: String,
}

impl PlayOptions {
    /// Checks the options before any work: an effort of 1 to [`MAX_EFFORT`] shots, at least
    /// one stroke, and every standard deviation of the noise finite and not negative.
    pub fn check(&self) -> Result<(), OptionsError> {
        let fail = |key: &str, reason: String| OptionsError {
            key: key.to_string(),
            reason,
        };
        if !(1..=MAX_EFFORT).contains(&self.effort) {
            return Err(fail(
                "effort",
                format!(
                    "1 to {MAX_EFFORT} simulated shots per stroke, got {}",
                    self.effort
                ),
            ));
        }
        if self.max_strokes == 0 {
            return Err(fail("max_strokes", "at least 1".into()));
        }
        match self.noise.check() {
            Err(snooker_planner::PlanError::BadInput { field, reason }) => {
                Err(fail(&field.to_string(), reason))
            }
            _ => Ok(()),
        }
    }
}

/// How long to play.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Until {
    /// Until the player at the table misses or fouls (one break), or the frame ends.
    Visit,
    /// Until the frame ends (both sides played).
    Frame,
}

/// How to play.
#[derive(Debug, Clone, PartialEq)]
pub struct PlayOptions {
    /// The execution noise added to every stroke.
    pub noise: Noise,
    /// The seed every random draw comes from.
    pub seed: u64,
    /// The search's budget per stroke, in simulated shots.
    pub effort: u64,
    /// A visit or a frame.
    pub until: Until,
    /// Most strokes played: a frame that has not ended by then stops there.
    pub max_strokes: usize,
    /// Counts the shots the agents simulate and says when to stop (the default: never).
    pub watch: Watch,
}

impl Default for PlayOptions {
    fn default() -> PlayOptions {
        PlayOptions {
            noise: Noise::STANDARD,
            seed: 1,
            effort: DEFAULT_EFFORT,
            until: Until::Visit,
            max_strokes: DEFAULT_MAX_STROKES,
            watch: Watch::default(),
        }
    }
}

/// One stroke played.
#[derive(Debug, Clone)]
pub struct StrokeRecord {
    /// Its number, from 1.
    pub number: u64,
    /// The player at the table.
    pub player: Side,
    /// The agent that chose it (`player`, `greedy`).
    pub agent: &'static str,
    /// The frame the stroke was played from: the cue ball placed and the nomination made.
    pub frame: Frame,
    /// What the agent decided.
    pub decision: Decision,
    /// The strike played: the one meant, plus the execution noise.
    pub executed: Cue,
    /// The simulated shot.
    pub shot: Shot,
    /// The referee's verdict.
    pub verdict: Verdict,
    /// Wall time of the decision, s.
    pub decision_time: f64,
}

/// How the play ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum End {
    /// The player at the table missed or fouled (a visit).
    VisitOver,
    /// The frame ended.
    FrameOver {
        /// The winner.
        winner: Side,
        /// The final scores.
        scores: [u32; 2],
    },
    /// The stroke cap was reached.
    StrokeCap,
}

/// Strokes played and how it ended.
#[derive(Debug, Clone)]
pub struct Game {
    /// The strokes, in order.
    pub strokes: Vec<StrokeRecord>,
    /// How it ended.
    pub end: End,
    /// The frame left (None when the frame is over).
    pub last: Option<Frame>,
}

impl Game {
    /// Points scored by `player`'s legal pots.
    pub fn points(&self, player: Side) -> u32 {
        self.strokes
            .iter()
            .filter(|s| s.player == player)
            .map(|s| s.verdict.points)
            .sum()
    }
}

/// Why play stopped short.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlayError {
    /// An option out of its range (nothing was played).
    #[error(transparent)]
    Options(#[from] OptionsError),
    /// No stroke could be chosen.
    #[error("stroke {stroke}: {source}")]
    Choose {
        /// The stroke's number.
        stroke: u64,
        /// Why.
        source: ChooseError,
    },
    /// The stroke chosen could not be played or judged (a bug of the agent's, or a shot the
    /// engine could not finish).
    #[error("stroke {stroke}: {source}")]
    Play {
        /// The stroke's number.
        stroke: u64,
        /// Why.
        source: snooker_rules::PlayError,
    },
}

/// The strike played when `intended` is meant for the cue ball of `frame`: the execution
/// noise of `noise` added, drawn for stroke `stroke` of a run seeded `seed` (its own stream,
/// apart from the agents' samples).
pub fn executed(frame: &Frame, intended: &Cue, noise: &Noise, seed: u64, stroke: u64) -> Cue {
    let Some(i) = frame.cue_index() else {
        return *intended;
    };
    let mut rng = rng_for(seed, &[stroke, u64::MAX]);
    noise.apply(intended, &frame.balls()[i].state, frame.params(), &mut rng)
}

/// The frame `frame` with the decision's choices made: the cue ball placed, the nomination.
pub fn with_choices(frame: &Frame, d: &Decision) -> Result<Frame, snooker_rules::FrameError> {
    let placed = match d.placement {
        Some(at) => frame.with_cue_ball_at(at)?,
        None => frame.clone(),
    };
    placed.with_nomination(d.nominated)
}

/// Plays from `frame`: `agents[p]` chooses for player p, each stroke is played with the noise
/// and judged, until `opts.until` says stop (or the stroke cap). `on_stroke` sees each stroke
/// as it is played. Once `opts.watch` is cancelled no further stroke is decided or played:
/// the play stops with [`ChooseError::Cancelled`] (the strokes seen by `on_stroke` stand).
pub fn play(
    frame: &Frame,
    agents: [&dyn Agent; 2],
    opts: &PlayOptions,
    mut on_stroke: impl FnMut(&StrokeRecord),
) -> Result<Game, PlayError> {
    opts.check()?;
    let mut frame = frame.clone();
    let first = frame.state().to_play;
    let mut strokes = Vec::new();
    for number in 1..=opts.max_strokes as u64 {
        let player = frame.state().to_play;
        let agent = agents[player as usize];
        let ctx = Context {
            noise: opts.noise,
            seed: opts.seed,
            stroke: number,
            effort: opts.effort,
            watch: opts.watch.clone(),
        };
        let cancelled = || PlayError::Choose {
            stroke: number,
            source: ChooseError::Cancelled,
        };
        if opts.watch.is_cancelled() {
            return Err(cancelled());
        }
        let start = Instant::now();
        let decision = agent
            .choose(&frame, &ctx)
            .map_err(|source| PlayError::Choose {
                stroke: number,
                source,
            })?;
        if opts.watch.is_cancelled() {
            return Err(cancelled());
        }
        let decision_time = start.elapsed().as_secs_f64();
        let chosen = with_choices(&frame, &decision).map_err(|e| PlayError::Choose {
            stroke: number,
            source: e.into(),
        })?;
        let executed = executed(&chosen, &decision.strike, &opts.noise, opts.seed, number);
        let played = chosen.play(&executed).map_err(|source| PlayError::Play {
            stroke: number,
            source,
        })?;
        let next = chosen.next(&played.verdict);
        let record = StrokeRecord {
            number,
            player,
            agent: agent.name(),
            frame: chosen,
            decision,
            executed,
            shot: played.shot,
            verdict: played.verdict,
            decision_time,
        };
        on_stroke(&record);
        strokes.push(record);
        match next {
            Next::Over { winner, scores } => {
                return Ok(Game {
                    strokes,
                    end: End::FrameOver { winner, scores },
                    last: None,
                });
            }
            Next::Play(f) => {
                frame = *f;
                if opts.until == Until::Visit && frame.state().to_play != first {
                    return Ok(Game {
                        strokes,
                        end: End::VisitOver,
                        last: Some(frame),
                    });
                }
            }
        }
    }
    Ok(Game {
        strokes,
        end: End::StrokeCap,
        last: Some(frame),
    })
}
