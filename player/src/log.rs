//! The play log (formats.md, "Play log"): one JSON line per stroke, in the contract's field
//! order: `stroke`, `player`, `frame` (the Frame TOML before the stroke, the cue ball placed and
//! the nomination made, no `[cue]`), `nominated`, `intended`, `executed`, `plan` (`pot`,
//! `pocket`, `kind`, `pot_probability`, `cue_to`), `referee` (the Referee result without
//! `shot`), `decision_time`. Extensions: `agent`; in `plan`, `ball` (the ball the cue ball is
//! sent at first), `via`, `value` (expected points), `samples` and `alternatives` (the next
//! best strokes considered, each as `plan`); `shots_simulated` (to decide).

use crate::decision::Considered;
use crate::game::StrokeRecord;
use serde::Serialize;
use snooker_planner::StrikeSpec;
use snooker_rules::{Player, RefereeReport};

/// `plan`.
#[derive(Debug, Serialize)]
pub struct LogPlan<'a> {
    /// The plan chosen (its fields flattened into `plan`).
    #[serde(flatten)]
    pub chosen: &'a Considered,
    /// The next best strokes considered.
    pub alternatives: &'a [Considered],
}

/// One line of the play log.
#[derive(Debug, Serialize)]
pub struct LogLine<'a> {
    /// The stroke's number, from 1.
    pub stroke: u64,
    /// The player at the table.
    pub player: Player,
    /// The frame before the stroke (TOML), with the player's choices.
    pub frame: String,
    /// The nominated colour, `""` for none.
    pub nominated: &'static str,
    /// The strike meant.
    pub intended: StrikeSpec,
    /// The strike played (meant + execution noise).
    pub executed: StrikeSpec,
    /// What was planned.
    pub plan: LogPlan<'a>,
    /// The referee's result of the executed strike, without `shot`.
    pub referee: RefereeReport<'a>,
    /// Wall time of the decision, s.
    pub decision_time: f64,
    /// The agent that chose the stroke.
    pub agent: &'static str,
    /// Shots simulated to decide.
    pub shots_simulated: u64,
}

impl StrokeRecord {
    /// Its line of the play log.
    pub fn log_line(&self) -> LogLine<'_> {
        let cue_id = self
            .frame
            .cue_index()
            .map_or("cue".to_string(), |i| self.frame.balls()[i].id.clone());
        LogLine {
            stroke: self.number,
            player: self.player,
            frame: self.frame.to_toml(None),
            nominated: self.frame.state().nominated.map_or("", |c| c.name()),
            intended: StrikeSpec::new(&cue_id, &self.decision.strike),
            executed: StrikeSpec::new(&cue_id, &self.executed),
            plan: LogPlan {
                chosen: &self.decision.plan,
                alternatives: &self.decision.alternatives,
            },
            referee: self.verdict.report(None),
            decision_time: self.decision_time,
            agent: self.agent,
            shots_simulated: self.decision.shots,
        }
    }

    /// Its line of the play log as JSON (no newline).
    pub fn log_json(&self) -> String {
        serde_json::to_string(&self.log_line()).expect("JSON of finite numbers")
    }
}
