//! The state of a frame between strokes (formats.md, "Frame", the `[frame]` table): the ball
//! on, the nominated colour, the scores, whose turn it is, the cue ball in hand, a free ball.

use crate::colour::Colour;
use serde::de::{self, Deserializer, Visitor};
use serde::{Deserialize, Serialize, Serializer};
use std::fmt;

/// The ball on (WPBSA Section 2 Rule 11 "Ball On").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum On {
    /// Any red (the player's first stroke of a visit while reds remain, and after each colour).
    Red,
    /// Any colour, the one nominated (after a red was potted).
    Colour,
    /// One colour of the closing sequence, yellow to black, once the reds are gone.
    Closing(Colour),
}

impl On {
    /// Every name the contract allows: `red`, `colour`, then the colours.
    pub const NAMES: [&'static str; 8] = [
        "red", "colour", "yellow", "green", "brown", "blue", "pink", "black",
    ];

    /// Its name in files and JSON.
    pub fn name(self) -> &'static str {
        match self {
            On::Red => "red",
            On::Colour => "colour",
            On::Closing(c) => c.name(),
        }
    }

    /// The ball on of this name.
    pub fn from_name(name: &str) -> Option<On> {
        match name {
            "red" => Some(On::Red),
            "colour" => Some(On::Colour),
            other => Colour::from_name(other).map(On::Closing),
        }
    }
}

impl fmt::Display for On {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl Serialize for On {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl<'de> Deserialize<'de> for On {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Name;
        impl Visitor<'_> for Name {
            type Value = On;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                write!(f, "one of {}", On::NAMES.join(", "))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<On, E> {
                On::from_name(v).ok_or_else(|| {
                    E::custom(format!(
                        "unknown ball on \"{v}\", expected one of {}",
                        On::NAMES.join(", ")
                    ))
                })
            }
        }
        d.deserialize_str(Name)
    }
}

/// A player: 0 or 1.
pub type Player = u8;

/// The other player.
pub fn opponent(p: Player) -> Player {
    1 - p.min(1)
}

/// The state of a frame between strokes: everything of the `[frame]` table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FrameState {
    /// The ball on.
    pub on: On,
    /// The colour nominated for the stroke (with `on = Colour`, or the free ball), if chosen.
    pub nominated: Option<Colour>,
    /// Points of player 0 and player 1.
    pub scores: [u32; 2],
    /// The player at the table (0 or 1).
    pub to_play: Player,
    /// The cue ball is in hand: played from the D.
    pub ball_in_hand: bool,
    /// Who played the first stroke of the frame (plays first after a re-spotted black).
    pub first_player: Player,
    /// The player was awarded a free ball: `nominated` is played as the ball on.
    pub free_ball: bool,
}

impl FrameState {
    /// The start of a frame: reds on, no score, `first_player` to break off from the D.
    pub fn start(first_player: Player) -> FrameState {
        FrameState {
            on: On::Red,
            nominated: None,
            scores: [0, 0],
            to_play: first_player,
            ball_in_hand: true,
            first_player,
            free_ball: false,
        }
    }
}

/// `nominated` in a file: a colour's name, or `""` for none (as the referee's `next` writes it).
pub(crate) fn deserialize_nominated<'de, D: Deserializer<'de>>(
    d: D,
) -> Result<Option<Colour>, D::Error> {
    struct Name;
    impl Visitor<'_> for Name {
        type Value = Option<Colour>;
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            write!(
                f,
                "a colour (yellow, green, brown, blue, pink, black) or \"\""
            )
        }
        fn visit_str<E: de::Error>(self, v: &str) -> Result<Option<Colour>, E> {
            if v.is_empty() {
                return Ok(None);
            }
            Colour::from_name(v).map(Some).ok_or_else(|| {
                E::custom(format!(
                    "\"{v}\" is not a colour to nominate (yellow, green, brown, blue, pink, \
                     black; a red is never nominated)"
                ))
            })
        }
    }
    d.deserialize_str(Name)
}

/// The highest score a frame may carry, points: far beyond any frame (147 is the highest
/// break, fouls score at most 7 a stroke), and far enough below the 32-bit limit that no
/// number of strokes a run can play takes a score past it (about 470 million strokes of 7).
pub const MAX_SCORE: u32 = 1_000_000_000;

/// `scores`: exactly two non-negative integers; anything else is one error at the key itself.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Scores(pub [u32; 2]);

/// One element of `scores` as given: a non-negative integer that fits, or what it was instead.
enum Score {
    Points(u32),
    Not(String),
}

impl<'de> Deserialize<'de> for Score {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Any;
        impl<'de> Visitor<'de> for Any {
            type Value = Score;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                write!(f, "anything")
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Score, E> {
                Ok(u32::try_from(v).map_or(Score::Not(v.to_string()), Score::Points))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Score, E> {
                match u64::try_from(v) {
                    Ok(v) => self.visit_u64(v),
                    Err(_) => Ok(Score::Not(v.to_string())),
                }
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Score, E> {
                Ok(Score::Not(v.to_string()))
            }
            fn visit_bool<E: de::Error>(self, v: bool) -> Result<Score, E> {
                Ok(Score::Not(v.to_string()))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Score, E> {
                Ok(Score::Not(format!("\"{v}\"")))
            }
            fn visit_seq<A: de::SeqAccess<'de>>(self, mut seq: A) -> Result<Score, A::Error> {
                while seq.next_element::<de::IgnoredAny>()?.is_some() {}
                Ok(Score::Not("an array".into()))
            }
            fn visit_map<A: de::MapAccess<'de>>(self, mut map: A) -> Result<Score, A::Error> {
                while map
                    .next_entry::<de::IgnoredAny, de::IgnoredAny>()?
                    .is_some()
                {}
                Ok(Score::Not("a table".into()))
            }
        }
        d.deserialize_any(Any)
    }
}

impl<'de> Deserialize<'de> for Scores {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        const WHAT: &str = "must be two non-negative integers, the points of player 0 and player 1";
        struct Pair;
        impl<'de> Visitor<'de> for Pair {
            type Value = Scores;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                write!(f, "two non-negative integers")
            }
            fn visit_seq<A: de::SeqAccess<'de>>(self, mut seq: A) -> Result<Scores, A::Error> {
                let mut out = Vec::new();
                while let Some(v) = seq.next_element::<Score>()? {
                    out.push(v);
                }
                match out[..] {
                    [Score::Points(a), Score::Points(b)] => Ok(Scores([a, b])),
                    [_, _] => {
                        let bad = out.iter().find_map(|v| match v {
                            Score::Not(s) => Some(s.clone()),
                            Score::Points(_) => None,
                        });
                        Err(de::Error::custom(format!(
                            "{WHAT}, got {}",
                            bad.unwrap_or_default()
                        )))
                    }
                    _ => Err(de::Error::custom(format!(
                        "{WHAT}, got {} values",
                        out.len()
                    ))),
                }
            }
        }
        d.deserialize_seq(Pair)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for n in On::NAMES {
            assert_eq!(On::from_name(n).unwrap().name(), n);
        }
        assert_eq!(On::from_name("purple"), None);
        assert_eq!(opponent(0), 1);
        assert_eq!(opponent(1), 0);
    }
}
