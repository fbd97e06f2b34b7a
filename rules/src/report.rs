//! The referee's JSON (formats.md, "Referee result"), as typed structs in the contract's
//! field order: `legal`, `foul`, `first_hit`, `potted`, `off_table`, `points`, `scores`,
//! `next`, `respotted`, `frame_over`, `winner`, `shot`. Extensions: `foul.reasons` (every
//! reason that applies, in order).

use crate::foul::FoulReason;
use crate::state::{On, Player};
use crate::verdict::Verdict;
use serde::Serialize;

/// The referee's result of one stroke.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RefereeReport<'a, S: Serialize = snooker_scene::result::ShotRecord> {
    /// No foul.
    pub legal: bool,
    /// The foul, `null` for a legal stroke.
    pub foul: Option<FoulReport>,
    /// The ball first hit, `null` when none.
    pub first_hit: Option<&'a str>,
    /// The object balls potted, in time order.
    pub potted: &'a [String],
    /// The balls forced off the table, in time order.
    pub off_table: &'a [String],
    /// Points scored by the player at the table.
    pub points: u32,
    /// The scores after the stroke.
    pub scores: [u32; 2],
    /// The next stroke, `null` when the frame is over.
    pub next: Option<NextReport>,
    /// The colours respotted, in the order placed.
    pub respotted: Vec<RespotReport<'a>>,
    /// The frame is over.
    pub frame_over: bool,
    /// The winner when the frame is over, else `null`.
    pub winner: Option<Player>,
    /// The result document of the simulated strike (omitted in the play log).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shot: Option<S>,
}

/// `foul`.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct FoulReport {
    /// The first reason that applies, in the contract's order.
    pub reason: FoulReason,
    /// Points to the opponent.
    pub points: u32,
    /// Every reason that applies, in order (an extension of the contract).
    pub reasons: Vec<FoulReason>,
}

/// `next`.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct NextReport {
    /// The player at the table.
    pub to_play: Player,
    /// The ball on.
    pub on: On,
    /// Always `""`: the nomination is the next player's to make.
    pub nominated: &'static str,
    /// The cue ball in hand.
    pub ball_in_hand: bool,
    /// A free ball awarded.
    pub free_ball: bool,
}

/// One entry of `respotted`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RespotReport<'a> {
    /// The ball's id.
    pub ball: &'a str,
    /// Where its centre was placed, m.
    pub pos: [f64; 2],
}

impl Verdict {
    /// The referee's result of this verdict, with `shot` (the strike's result document) if
    /// given.
    pub fn report<S: Serialize>(&self, shot: Option<S>) -> RefereeReport<'_, S> {
        RefereeReport {
            legal: self.legal(),
            foul: self.foul.as_ref().map(|f| FoulReport {
                reason: f.reason,
                points: f.points,
                reasons: f.reasons.clone(),
            }),
            first_hit: self.first_hit.as_deref(),
            potted: &self.potted,
            off_table: &self.off_table,
            points: self.points,
            scores: self.scores,
            next: self.next.map(|n| NextReport {
                to_play: n.to_play,
                on: n.on,
                nominated: n.nominated.map_or("", |c| c.name()),
                ball_in_hand: n.ball_in_hand,
                free_ball: n.free_ball,
            }),
            respotted: self
                .respotted
                .iter()
                .map(|(id, r)| RespotReport {
                    ball: id,
                    pos: [r.pos.x, r.pos.y],
                })
                .collect(),
            frame_over: self.frame_over(),
            winner: self.winner,
            shot,
        }
    }
}
