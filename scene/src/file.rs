//! The scene file's schema (TOML; the contract of docs/formats.md, with its extensions):
//! every key typed, unknown keys rejected, arrays of exactly the documented length. The same
//! types are the scene builder of code that makes scenes (the batch sets, the fuzz harness,
//! the planner's test positions, Python's dicts): built with [`SceneFile::new`] and its
//! `with_*` methods, checked by [`SceneFile::build`] exactly as a file is, and written as
//! TOML or JSON that reads back to the bit.

use serde::de::{self, DeserializeSeed, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde::ser::{SerializeMap, Serializer};
use serde::{Deserialize, Serialize};
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

impl<const N: usize> Serialize for Numbers<N> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.0.as_slice().serialize(s)
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
/// ([`IgnoredAny`]: `snooker simulate` runs a frame file as the scene it is). The `[frame]`
/// table is not written by [`SceneFile::to_toml`]: a frame writes its own.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile<X = IgnoredAny> {
    /// Free text (default: the file's stem).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// The table.
    #[serde(default, skip_serializing_if = "TableSpec::is_default")]
    pub table: TableSpec,
    /// Parameter overrides.
    #[serde(default, skip_serializing_if = "ParamOverrides::is_empty")]
    pub params: ParamOverrides,
    /// Impact models.
    #[serde(default, skip_serializing_if = "ModelSpec::is_default")]
    pub models: ModelSpec,
    /// A named layout of balls (`break-off`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub layout: Option<String>,
    /// Listed balls (added, or replacing a layout ball of the same id).
    #[serde(default)]
    pub balls: Vec<BallSpec>,
    /// The cue strike.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cue: Option<CueSpec>,
    /// Limits of the simulation.
    #[serde(default, skip_serializing_if = "SimSpec::is_default")]
    pub sim: SimSpec,
    /// `[frame]`: the state of a game of snooker, read by whoever asked for `X`.
    #[serde(skip_serializing)]
    pub frame: Option<X>,
}

impl SceneFile {
    /// An empty scene on the snooker table, every parameter and model the default.
    pub fn new() -> SceneFile {
        SceneFile::default()
    }

    /// The scene with a name.
    pub fn with_name(mut self, name: impl Into<String>) -> SceneFile {
        self.name = Some(name.into());
        self
    }

    /// The scene with a named layout (`break-off`).
    pub fn with_layout(mut self, layout: impl Into<String>) -> SceneFile {
        self.layout = Some(layout.into());
        self
    }

    /// The scene on the open table (endless cloth, no cushions, no pockets).
    pub fn on_open_table(mut self) -> SceneFile {
        self.table.kind = TableKind::Open;
        self
    }

    /// The scene with parameter `name` (a [`PARAMS`] name) set to `value` (replacing a value
    /// set before: the file written has each key once); an unknown name is refused by
    /// [`SceneFile::build`], naming its key.
    pub fn with_param(mut self, name: &'static str, value: f64) -> SceneFile {
        match self.params.0.iter_mut().find(|(n, _)| *n == name) {
            Some(p) => p.1 = value,
            None => self.params.0.push((name, value)),
        }
        self
    }

    /// The scene with these impact models.
    pub fn with_models(mut self, ball_ball: BallBallModel, cushion: CushionModel) -> SceneFile {
        self.models = ModelSpec {
            ball_ball: Some(ball_ball),
            cushion: Some(cushion),
        };
        self
    }

    /// The scene with one more ball listed.
    pub fn with_ball(mut self, ball: BallSpec) -> SceneFile {
        self.balls.push(ball);
        self
    }

    /// The scene with a cue strike.
    pub fn with_strike(mut self, cue: CueSpec) -> SceneFile {
        self.cue = Some(cue);
        self
    }

    /// The scene file as TOML; every number reads back to the bit.
    pub fn to_toml(&self) -> String {
        toml::to_string(self).expect("a scene serialises to TOML")
    }

    /// The scene as one JSON object (a batch's line), if every number is finite (JSON has no
    /// NaN or infinity).
    pub fn to_json(&self) -> Option<String> {
        serde_json::to_string(self).ok()
    }

    /// Checks and builds the scene, as a file is: `file` names it in error messages.
    pub fn build(self, file: &str) -> Result<crate::Scene, crate::SceneError> {
        crate::build::build(self, file)
    }
}

/// `[table]`.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TableSpec {
    /// Snooker table or the open cloth.
    #[serde(default)]
    pub kind: TableKind,
    /// Corner pocket opening between the jaw points, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub corner_mouth: Option<f64>,
    /// Middle pocket opening, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub middle_mouth: Option<f64>,
    /// Jaw radius, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub jaw_radius: Option<f64>,
    /// How far behind the jaw line a ball's centre must go to drop, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fall_depth: Option<f64>,
}

impl TableSpec {
    /// True for the default table (nothing to write).
    pub fn is_default(&self) -> bool {
        *self == TableSpec::default()
    }
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

    /// True when nothing is overridden.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

impl Serialize for ParamOverrides {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (name, v) in &self.0 {
            map.serialize_entry(name, v)?;
        }
        map.end()
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
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelSpec {
    /// Ball-ball impact model.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ball_ball: Option<BallBallModel>,
    /// Ball-cushion impact model.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cushion: Option<CushionModel>,
}

impl ModelSpec {
    /// True when no model is named.
    pub fn is_default(&self) -> bool {
        *self == ModelSpec::default()
    }
}

/// One `[[balls]]` entry.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BallSpec {
    /// Unique name; its prefix names the colour.
    pub id: String,
    /// Centre [x, y], m.
    pub pos: Numbers<2>,
    /// Velocity, m/s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vel: Option<Numbers<3>>,
    /// Angular velocity, rad/s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spin: Option<Numbers<3>>,
    /// Colour, overriding the id's prefix.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub kind: Option<BallKind>,
}

impl BallSpec {
    /// Ball `id` at rest with its centre at `pos` = [x, y], m.
    pub fn at(id: impl Into<String>, pos: [f64; 2]) -> BallSpec {
        BallSpec {
            id: id.into(),
            pos: Numbers(pos),
            vel: None,
            spin: None,
            kind: None,
        }
    }

    /// The ball moving at `vel`, m/s.
    pub fn with_vel(mut self, vel: [f64; 3]) -> BallSpec {
        self.vel = Some(Numbers(vel));
        self
    }

    /// The ball spinning at `spin`, rad/s.
    pub fn with_spin(mut self, spin: [f64; 3]) -> BallSpec {
        self.spin = Some(Numbers(spin));
        self
    }

    /// The ball of colour `kind`, whatever its id.
    pub fn with_kind(mut self, kind: BallKind) -> BallSpec {
        self.kind = Some(kind);
        self
    }
}

/// `[cue]`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
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

impl CueSpec {
    /// A strike of ball `ball` at cue speed `speed` (m/s) along heading `aim` (rad): centre
    /// ball, the cue level.
    pub fn new(ball: impl Into<String>, speed: f64, aim: f64) -> CueSpec {
        CueSpec {
            ball: ball.into(),
            speed,
            aim,
            offset: Numbers([0.0, 0.0]),
            elevation: 0.0,
        }
    }

    /// The strike with the cue's axis offset [side, height], m.
    pub fn with_offset(mut self, offset: [f64; 2]) -> CueSpec {
        self.offset = Numbers(offset);
        self
    }

    /// The strike with the cue raised by `elevation`, rad.
    pub fn with_elevation(mut self, elevation: f64) -> CueSpec {
        self.elevation = elevation;
        self
    }
}

/// `[sim]`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SimSpec {
    /// Event cap.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_events: Option<usize>,
    /// Simulated time within which every ball must stop, s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_time: Option<f64>,
    /// Stop cleanly here, s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub horizon: Option<f64>,
}

impl SimSpec {
    /// True when no limit is given.
    pub fn is_default(&self) -> bool {
        *self == SimSpec::default()
    }
}
