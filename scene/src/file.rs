//! The scene file's schema (TOML; the contract in `shared/formats.md`, extended in the README):
//! every key typed, unknown keys rejected, arrays of exactly the documented length.

use serde::Deserialize;
use serde::de::{self, DeserializeSeed, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};
use snooker_engine::params::PARAMS;
use snooker_engine::{BallBallModel, BallKind, CushionModel, TableKind};
use std::fmt;

/// Exactly `N` numbers, as a TOML array (`pos = [x, y]`, `vel = [vx, vy, vz]`): a shorter or
/// longer array is an error naming the key, never silently cut or padded.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Numbers<const N: usize>(pub [f64; N]);

impl<const N: usize> Default for Numbers<N> {
    fn default() -> Self {
        Numbers([0.0; N])
    }
}

impl<'de, const N: usize> Deserialize<'de> for Numbers<N> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Exact<const N: usize>;
        impl<'de, const N: usize> Visitor<'de> for Exact<N> {
            type Value = Numbers<N>;

            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                write!(f, "an array of exactly {N} numbers")
            }

            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
                let mut out = [0.0; N];
                let mut n = 0;
                while let Some(v) = seq.next_element::<f64>()? {
                    if n < N {
                        out[n] = v;
                    }
                    n += 1;
                }
                if n != N {
                    return Err(de::Error::invalid_length(n, &self));
                }
                Ok(Numbers(out))
            }
        }
        d.deserialize_seq(Exact::<N>)
    }
}

/// A whole scene file. `X` is what its `[frame]` table is read as: a frame of snooker
/// (formats.md, "Frame") for the rules crate; for a scene alone the table is not read
/// ([`IgnoredAny`]: `snooker simulate` runs a frame file as the scene it is).
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct SceneFile<X = IgnoredAny> {
    /// Free text (default: the file's stem).
    pub name: Option<String>,
    /// The table.
    #[serde(default)]
    pub table: TableSpec,
    /// Parameter overrides.
    #[serde(default)]
    pub params: ParamOverrides,
    /// Impact models.
    #[serde(default)]
    pub models: ModelSpec,
    /// A named layout of balls (`break-off`).
    pub layout: Option<String>,
    /// Listed balls (added, or replacing a layout ball of the same id).
    #[serde(default)]
    pub balls: Vec<BallSpec>,
    /// The cue strike.
    pub cue: Option<CueSpec>,
    /// Limits of the simulation.
    #[serde(default)]
    pub sim: SimSpec,
    /// `[frame]`: the state of a game of snooker, read by whoever asked for `X`.
    pub frame: Option<X>,
}

/// `[table]`.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct TableSpec {
    /// Snooker table or the open cloth.
    #[serde(default)]
    pub kind: TableKind,
    /// Corner pocket opening between the jaw points, m.
    pub corner_mouth: Option<f64>,
    /// Middle pocket opening, m.
    pub middle_mouth: Option<f64>,
    /// Jaw radius, m.
    pub jaw_radius: Option<f64>,
    /// How far behind the jaw line a ball's centre must go to drop, m.
    pub fall_depth: Option<f64>,
}

/// `[params]`: parameters by their documented names ([`snooker_engine::params::PARAMS`]), in
/// the file's order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ParamOverrides(pub Vec<(&'static str, f64)>);

impl ParamOverrides {
    /// True when `name` is given.
    pub fn has(&self, name: &str) -> bool {
        self.0.iter().any(|(n, _)| *n == name)
    }
}

/// The value of the parameter named by the key just read: an unknown name fails here, so that
/// the error names the key (`params.mu_slid`) and its line.
struct ParamValue<'a>(&'a str);

impl<'de> DeserializeSeed<'de> for ParamValue<'_> {
    type Value = (&'static str, f64);

    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        let Some(info) = PARAMS.iter().find(|i| i.name == self.0) else {
            let known: Vec<String> = PARAMS.iter().map(|i| format!("`{}`", i.name)).collect();
            return Err(de::Error::custom(format!(
                "unknown field `{}`, expected one of {}",
                self.0,
                known.join(", ")
            )));
        };
        Ok((info.name, f64::deserialize(d)?))
    }
}

impl<'de> Deserialize<'de> for ParamOverrides {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Table;
        impl<'de> Visitor<'de> for Table {
            type Value = ParamOverrides;

            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                write!(f, "a table of parameters, NAME = number")
            }

            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
                let mut out = Vec::new();
                while let Some(key) = map.next_key::<String>()? {
                    out.push(map.next_value_seed(ParamValue(&key))?);
                }
                Ok(ParamOverrides(out))
            }
        }
        d.deserialize_map(Table)
    }
}

/// `[models]`.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct ModelSpec {
    /// Ball-ball impact model.
    pub ball_ball: Option<BallBallModel>,
    /// Ball-cushion impact model.
    pub cushion: Option<CushionModel>,
}

/// One `[[balls]]` entry.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BallSpec {
    /// Unique name; its prefix names the colour.
    pub id: String,
    /// Centre [x, y], m.
    pub pos: Numbers<2>,
    /// Velocity, m/s.
    pub vel: Option<Numbers<3>>,
    /// Angular velocity, rad/s.
    pub spin: Option<Numbers<3>>,
    /// Colour, overriding the id's prefix.
    pub kind: Option<BallKind>,
}

/// `[cue]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CueSpec {
    /// The ball struck.
    pub ball: String,
    /// Cue speed at impact, m/s.
    pub speed: f64,
    /// Heading of the cue, rad.
    pub aim: f64,
    /// Cue axis offset at the ball [side, height], m.
    #[serde(default)]
    pub offset: Numbers<2>,
    /// Cue inclination, rad.
    #[serde(default)]
    pub elevation: f64,
}

/// `[sim]`.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct SimSpec {
    /// Event cap.
    pub max_events: Option<usize>,
    /// Simulated time within which every ball must stop, s.
    pub max_time: Option<f64>,
    /// Stop cleanly here, s.
    pub horizon: Option<f64>,
}
