//! Fouls: their reasons, named in the contract's order (formats.md, "Referee result"), and
//! their value (WPBSA Section 3 Rule 10 "Penalties": 4, or the value of the ball on, of the
//! ball first hit, or of a ball potted or forced off the table, whichever is highest; 7 at most).

use serde::{Deserialize, Serialize};

/// Why a stroke is a foul. The order is the contract's: the first that applies names the foul.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FoulReason {
    /// The cue ball hit no ball (WPBSA Section 3 Rule 10).
    NoBallHit,
    /// The first ball hit was not on, or a ball not on was hit at the same instant as one on
    /// (Section 3 Rule 10;
    /// Rule 6 "Hitting Two Balls Simultaneously").
    FirstHitNotOn,
    /// A ball not on was potted: a colour with reds on, a red with a colour on (Rule 10).
    BallNotOnPotted,
    /// The cue ball went into a pocket (Rule 10).
    CueBallPotted,
    /// A ball was forced off the table, the cue ball included (Rule 10; Section 2 Rule 14).
    OffTable,
    /// With a colour on, another colour was potted and the one on was not (Rule 10).
    WrongColourPotted,
    /// With a colour on, it was potted with another colour (Rule 10: two balls potted other
    /// than reds, or the free ball and a ball on).
    TwoColoursPotted,
    /// After a free ball stroke, the cue ball is snookered on every ball on by the free ball
    /// (Section 3 Rule 12(b)(ii); not when the pink and black are the only object balls). An
    /// extension of the contract's list, after its seven so that theirs keep their order.
    SnookeredByFreeBall,
    /// A ball the cue ball touched as the stroke began was moved by it: a push stroke
    /// (Section 3 Rule 8(b) "Touching Ball"; Rule 10). An extension, after the free ball's.
    PushStroke,
    /// The cue ball passed over an object ball ([`crate::jump`]; Section 2 Rule 20 "Jump
    /// Shot", Section 3 Rule 10). An extension, last in the order.
    JumpShot,
}

impl FoulReason {
    /// Every reason, in the contract's order.
    pub const ALL: [FoulReason; 10] = [
        FoulReason::NoBallHit,
        FoulReason::FirstHitNotOn,
        FoulReason::BallNotOnPotted,
        FoulReason::CueBallPotted,
        FoulReason::OffTable,
        FoulReason::WrongColourPotted,
        FoulReason::TwoColoursPotted,
        FoulReason::SnookeredByFreeBall,
        FoulReason::PushStroke,
        FoulReason::JumpShot,
    ];

    /// Its name in the referee's JSON.
    pub fn name(self) -> &'static str {
        match self {
            FoulReason::NoBallHit => "no_ball_hit",
            FoulReason::FirstHitNotOn => "first_hit_not_on",
            FoulReason::BallNotOnPotted => "ball_not_on_potted",
            FoulReason::CueBallPotted => "cue_ball_potted",
            FoulReason::OffTable => "off_table",
            FoulReason::WrongColourPotted => "wrong_colour_potted",
            FoulReason::TwoColoursPotted => "two_colours_potted",
            FoulReason::SnookeredByFreeBall => "snookered_by_free_ball",
            FoulReason::PushStroke => "push_stroke",
            FoulReason::JumpShot => "jump_shot",
        }
    }
}

impl std::fmt::Display for FoulReason {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The least a foul is worth, points (WPBSA Section 3 Rule 10).
pub const MIN_FOUL: u32 = 4;
/// The most a foul is worth, points.
pub const MAX_FOUL: u32 = 7;

/// A foul: the reason that names it, every reason that applies, and its value.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Foul {
    /// The first reason that applies, in the contract's order.
    pub reason: FoulReason,
    /// Every reason that applies, in that order (the first is `reason`).
    pub reasons: Vec<FoulReason>,
    /// Points awarded to the opponent.
    pub points: u32,
}

/// The value of a foul: [`MIN_FOUL`] or the highest of `values` (the ball on, the balls first
/// hit, the balls potted or forced off), at most [`MAX_FOUL`].
pub fn value(values: impl IntoIterator<Item = u32>) -> u32 {
    values.into_iter().fold(MIN_FOUL, u32::max).min(MAX_FOUL)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reasons_serialise_to_the_contract_names_in_its_order() {
        let names: Vec<String> = FoulReason::ALL
            .iter()
            .map(|r| {
                serde_json::to_value(r)
                    .unwrap()
                    .as_str()
                    .unwrap()
                    .to_string()
            })
            .collect();
        assert_eq!(
            names,
            [
                "no_ball_hit",
                "first_hit_not_on",
                "ball_not_on_potted",
                "cue_ball_potted",
                "off_table",
                "wrong_colour_potted",
                "two_colours_potted",
                "snookered_by_free_ball",
                "push_stroke",
                "jump_shot"
            ]
        );
        assert!(FoulReason::ALL.windows(2).all(|w| w[0] < w[1]));
        for r in FoulReason::ALL {
            assert_eq!(r.name(), names[r as usize]);
        }
        assert_eq!(value([1, 2]), 4);
        assert_eq!(value([5, 6]), 6);
        assert_eq!(value([]), 4);
    }
}
