//! The balls of snooker as the rules see them: reds, the six colours and their values
//! (WPBSA Section 2 Rule 4 "Balls"; Section 3 Rule 1: red 1, yellow 2, green 3, brown 4,
//! blue 5, pink 6, black 7).

use serde::{Deserialize, Serialize};
use snooker_engine::BallKind;

/// The six colours, in the order the closing sequence takes them (ascending value).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Colour {
    /// 2 points.
    Yellow,
    /// 3 points.
    Green,
    /// 4 points.
    Brown,
    /// 5 points.
    Blue,
    /// 6 points.
    Pink,
    /// 7 points.
    Black,
}

impl Colour {
    /// Every colour, lowest value first.
    pub const ALL: [Colour; 6] = [
        Colour::Yellow,
        Colour::Green,
        Colour::Brown,
        Colour::Blue,
        Colour::Pink,
        Colour::Black,
    ];

    /// Its value in points.
    pub fn value(self) -> u32 {
        match self {
            Colour::Yellow => 2,
            Colour::Green => 3,
            Colour::Brown => 4,
            Colour::Blue => 5,
            Colour::Pink => 6,
            Colour::Black => 7,
        }
    }

    /// Its name in files and JSON (the name of its spot too).
    pub fn name(self) -> &'static str {
        match self {
            Colour::Yellow => "yellow",
            Colour::Green => "green",
            Colour::Brown => "brown",
            Colour::Blue => "blue",
            Colour::Pink => "pink",
            Colour::Black => "black",
        }
    }

    /// The colour of this name.
    pub fn from_name(name: &str) -> Option<Colour> {
        Colour::ALL.into_iter().find(|c| c.name() == name)
    }

    /// The colour of a ball of this kind, if it is a colour.
    pub fn of(kind: BallKind) -> Option<Colour> {
        match kind {
            BallKind::Yellow => Some(Colour::Yellow),
            BallKind::Green => Some(Colour::Green),
            BallKind::Brown => Some(Colour::Brown),
            BallKind::Blue => Some(Colour::Blue),
            BallKind::Pink => Some(Colour::Pink),
            BallKind::Black => Some(Colour::Black),
            _ => None,
        }
    }

    /// The engine's kind of a ball of this colour.
    pub fn kind(self) -> BallKind {
        match self {
            Colour::Yellow => BallKind::Yellow,
            Colour::Green => BallKind::Green,
            Colour::Brown => BallKind::Brown,
            Colour::Blue => BallKind::Blue,
            Colour::Pink => BallKind::Pink,
            Colour::Black => BallKind::Black,
        }
    }

    /// The next colour of the closing sequence (none after the black).
    pub fn next(self) -> Option<Colour> {
        Colour::ALL.into_iter().find(|c| *c > self)
    }
}

impl std::fmt::Display for Colour {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The value of a ball of this kind in points: a red 1, a colour its value, the cue ball (or
/// any other ball) none.
pub fn value(kind: BallKind) -> u32 {
    match kind {
        BallKind::Red => 1,
        k => Colour::of(k).map_or(0, Colour::value),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_and_order_are_the_rules() {
        let values: Vec<u32> = Colour::ALL.iter().map(|c| c.value()).collect();
        assert_eq!(values, [2, 3, 4, 5, 6, 7]);
        assert_eq!(Colour::Brown.next(), Some(Colour::Blue));
        assert_eq!(Colour::Black.next(), None);
        assert_eq!(value(BallKind::Red), 1);
        assert_eq!(value(BallKind::Cue), 0);
        for c in Colour::ALL {
            assert_eq!(Colour::from_name(c.name()), Some(c));
            assert_eq!(Colour::of(c.kind()), Some(c));
        }
    }
}
