//! What can be wrong with a frame, a strike or a shot to judge: each a typed [`Problem`] at a
//! [`Key`] of the frame file (formats.md, "Frame"), so that a message names the key at fault.

use crate::colour::Colour;
use crate::state::On;
use snooker_engine::Vec3;
use std::fmt;

/// Where a problem is, as a key of the frame file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Key {
    /// A key of the `[frame]` table: `frame.NAME`.
    Frame(&'static str),
    /// A field of the ball at this index of the frame's balls (`balls[i].pos`; empty field:
    /// the ball itself). A frame read from a file names the ball's own key instead (a layout
    /// ball, or its index among the listed balls).
    Ball(usize, &'static str),
    /// Any other key: `table.kind`, `sim.horizon`, `cue.ball`, `balls`, `cue`.
    Other(&'static str),
}

impl fmt::Display for Key {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Key::Frame(k) => write!(f, "frame.{k}"),
            Key::Ball(i, "") => write!(f, "balls[{i}]"),
            Key::Ball(i, field) => write!(f, "balls[{i}].{field}"),
            Key::Other(k) => f.write_str(k),
        }
    }
}

/// Why a frame cannot be played or judged.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Problem {
    /// The open table has no spots, D or pockets.
    #[error("a frame of snooker needs the snooker table (its spots, the D and its pockets)")]
    NotSnookerTable,
    /// A snooker table other than one a frame file can describe.
    #[error(
        "a frame is played on the full-size snooker table, its pocket sizes (corner_mouth, middle_mouth, jaw_radius, fall_depth) the only choice a frame file has; this table differs, so its frame file would not read back"
    )]
    NotTheFilesTable,
    /// A ball that is not the cue ball, a red or a colour.
    #[error(
        "ball \"{id}\" is not a ball of snooker: its id or kind must name the cue ball, a red or a colour"
    )]
    NotSnookerBall {
        /// Its id.
        id: String,
    },
    /// A second cue ball.
    #[error("ball \"{id}\" is a second cue ball")]
    SecondCueBall {
        /// Its id.
        id: String,
    },
    /// A second ball of one colour.
    #[error("ball \"{id}\" is a second {colour}")]
    ColourTwice {
        /// Its id.
        id: String,
        /// The colour.
        colour: Colour,
    },
    /// A ball moving or spinning: a stroke starts with every ball at rest.
    #[error("ball \"{id}\" is moving: a stroke is played with every ball at rest")]
    Moving {
        /// Its id.
        id: String,
    },
    /// A ball whose centre is not a radius above the cloth: a stroke starts with every ball
    /// resting on it.
    #[error("ball \"{id}\" is {height} m off the cloth: a stroke is played with every ball on it")]
    OffTheCloth {
        /// Its id.
        id: String,
        /// Its centre's height above a ball resting on the cloth, m.
        height: f64,
    },
    /// Limits of the simulation that cannot be used ([`snooker_engine::SimOptions::validate`]).
    #[error("{0}")]
    Limits(String),
    /// A horizon would stop the shot before the balls rest.
    #[error("a stroke is judged once every ball has stopped: a frame takes no horizon")]
    Horizon,
    /// No black on the table.
    #[error("the black is not on the table (a frame ends with the black)")]
    NoBlack,
    /// `on = "red"` with no red on the table.
    #[error("on = \"red\" but no red is on the table")]
    NoRedOn,
    /// A colour missing while reds remain.
    #[error(
        "on = \"{on}\" but the {colour} is not on the table: until the reds are gone every colour is (potted colours are respotted)"
    )]
    ColourMissing {
        /// The ball on.
        on: On,
        /// The colour missing.
        colour: Colour,
    },
    /// A closing colour on with reds on the table.
    #[error(
        "on = \"{on}\" but reds remain on the table (the colours are taken in order once the reds are gone)"
    )]
    ClosingWithReds {
        /// The ball on.
        on: On,
    },
    /// A closing colour on that is not the lowest on the table.
    #[error(
        "on = \"{on}\" but the {lowest} is still on the table (the colours are taken in ascending order)"
    )]
    NotLowest {
        /// The ball on.
        on: On,
        /// The lowest colour on the table.
        lowest: Colour,
    },
    /// A closing colour on that is not on the table.
    #[error("on = \"{on}\" but the {on} is not on the table")]
    OnMissing {
        /// The ball on.
        on: On,
    },
    /// A colour of the closing sequence missing above the ball on.
    #[error(
        "on = \"{on}\" but the {colour} is not on the table (a colour potted in the closing sequence is always a lower one)"
    )]
    HigherMissing {
        /// The ball on.
        on: On,
        /// The colour missing.
        colour: Colour,
    },
    /// A stroke to judge with a colour or a free ball on and nothing nominated.
    #[error("a stroke with on = \"{on}\"{} needs the ball nominated (nominated = \"black\", ...){}", if *.free_ball { " and a free ball" } else { "" }, if *.free_ball { "; to decline the free ball and play the ball on, set free_ball = false" } else { "" })]
    NoNomination {
        /// The ball on.
        on: On,
        /// A free ball was awarded.
        free_ball: bool,
    },
    /// A nominated colour that is not on the table.
    #[error("the {colour} is nominated but not on the table")]
    NominatedMissing {
        /// The colour.
        colour: Colour,
    },
    /// A nomination with reds on and no free ball.
    #[error("with on = \"red\" and no free ball there is nothing to nominate")]
    NothingToNominate,
    /// A nomination in the closing sequence other than the ball on, without a free ball.
    #[error(
        "on = \"{on}\": only the {on} can be played (a free ball is needed to nominate the {nominated})"
    )]
    NominatedNotOn {
        /// The ball on.
        on: On,
        /// The colour nominated.
        nominated: Colour,
    },
    /// A free ball nominating the ball on itself.
    #[error("a free ball is a ball other than the ball on, not the {0} (WPBSA Section 2 Rule 13)")]
    FreeBallIsOn(Colour),
    /// A free ball while a colour is on after a red (only an incoming player, on the lowest ball on, has one).
    #[error(
        "a free ball is awarded to the incoming player after a foul, who is on a red or the lowest colour, never on = \"colour\""
    )]
    FreeBallOnColour,
    /// A score above [`crate::state::MAX_SCORE`].
    #[error(
        "{0} is above {max}, the most a frame's score may be (far beyond any frame; a score \
         near the 32-bit limit would overflow when points are added)",
        max = crate::state::MAX_SCORE
    )]
    ScoreTooHigh(u32),
    /// `to_play` or `first_player` not 0 or 1.
    #[error("must be 0 or 1 (player 0 or player 1), got {0}")]
    NotAPlayer(i64),
    /// No cue ball on the table and none in hand.
    #[error(
        "no cue ball on the table: list it in [[balls]] (id \"cue\"), or set ball_in_hand = true"
    )]
    NoCueBall,
    /// A cue ball in hand placed outside the D.
    #[error("the cue ball is in hand and must be placed on or within the lines of the D (WPBSA Section 3 Rule 5): ({:.4}, {:.4}) m is outside it", .0.x, .0.y)]
    OutsideD(Vec3),
    /// A cue ball in hand placed touching or overlapping another ball.
    #[error("the cue ball in hand may not be placed touching a ball: ({:.4}, {:.4}) m is {:.4} mm from ball \"{other}\" (centres 2R = {:.4} mm apart or closer)", .pos.x, .pos.y, .gap * 1e3, .two_r * 1e3)]
    Touching {
        /// The placement.
        pos: Vec3,
        /// The ball it touches.
        other: String,
        /// Distance between the centres, m.
        gap: f64,
        /// Twice the ball radius, m.
        two_r: f64,
    },
    /// A strike with the cue ball in hand and not placed.
    #[error(
        "the cue ball is in hand: place it in the D (a [[balls]] entry with id \"cue\") to strike it"
    )]
    NotPlaced,
    /// A placement asked for with the cue ball not in hand.
    #[error("the cue ball is not in hand: it is played from where it lies")]
    NotInHand,
    /// A strike on a ball other than the cue ball.
    #[error("the striker strikes the cue ball, not \"{0}\"")]
    NotTheCueBall(String),
    /// A strike the engine refuses (miscue, speed out of range...).
    #[error("{0}")]
    Strike(String),
    /// A frame played after another that is not the frame the stroke left.
    #[error("does not follow from the stroke before: {0}")]
    DoesNotFollow(String),
    /// No strike to judge.
    #[error("a frame to referee needs its [cue] strike")]
    NoStrike,
}

/// A frame that cannot be played or judged: the key at fault and why.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("key `{key}`: {problem}")]
pub struct FrameError {
    /// The key at fault.
    pub key: Key,
    /// Why.
    pub problem: Problem,
}

impl FrameError {
    /// A problem at a key.
    pub fn new(key: Key, problem: Problem) -> FrameError {
        FrameError { key, problem }
    }
}

/// A shot that cannot be judged against a frame.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum JudgeError {
    /// The frame is not ready for the stroke (no nomination, cue ball not placed).
    #[error(transparent)]
    Frame(#[from] FrameError),
    /// The shot's balls are not the frame's.
    #[error(
        "the shot was not simulated from this frame: its balls are {shot:?}, the frame's {frame:?}"
    )]
    ShotMismatch {
        /// The shot's ball ids.
        shot: Vec<String>,
        /// The frame's ball ids.
        frame: Vec<String>,
    },
    /// The shot stopped before every ball came to rest.
    #[error(
        "the shot stopped at its horizon with balls moving: a stroke is judged when every ball has stopped"
    )]
    NotAtRest,
    /// Not a point on the table where a colour could be spotted (never on a full-size table).
    #[error("no room on the table to spot the {0}")]
    NoRoomToSpot(Colour),
}
