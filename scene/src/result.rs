//! The JSON result of a shot (the contract in `docs/formats.md`; extended, never renamed) and
//! the human summary printed by `snooker simulate`.

use crate::Scene;
use serde::de::{MapAccess, Visitor};
use serde::ser::SerializeMap;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use snooker_engine::{BallState, EventKind, Models, Motion, Shot};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// Normal impact speed above which the thesis's rigid cushion model is not valid, m/s
/// (thesis §5.1.2, §6.2.5: the cushion deforms; data file `rigid_limit_speed`).
pub const CUSHION_RIGID_LIMIT: f64 = 2.5;

/// A map from ball ids (or parameter names) to values that keeps its entries in the order
/// given: the result lists balls in the scene's order and parameters in their declaration's,
/// which scripts reading the JSON by eye rely on (a `HashMap` would shuffle them).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct OrderedMap<V>(pub Vec<(String, V)>);

impl<V> OrderedMap<V> {
    /// The value under `key`, if any.
    pub fn get(&self, key: &str) -> Option<&V> {
        self.0.iter().find(|(k, _)| k == key).map(|(_, v)| v)
    }
}

impl<V: Serialize> Serialize for OrderedMap<V> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            map.serialize_entry(k, v)?;
        }
        map.end()
    }
}

impl<'de, V: Deserialize<'de>> Deserialize<'de> for OrderedMap<V> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Entries<V>(std::marker::PhantomData<V>);
        impl<'de, V: Deserialize<'de>> Visitor<'de> for Entries<V> {
            type Value = OrderedMap<V>;

            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a map")
            }

            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
                let mut out = Vec::new();
                while let Some(entry) = map.next_entry()? {
                    out.push(entry);
                }
                Ok(OrderedMap(out))
            }
        }
        d.deserialize_map(Entries(std::marker::PhantomData))
    }
}

/// A ball's state as the result gives it (formats.md: `pos`, `vel`, `spin`, `motion`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct BallRecord {
    /// Centre, m.
    pub pos: [f64; 3],
    /// Velocity, m/s.
    pub vel: [f64; 3],
    /// Angular velocity, rad/s.
    pub spin: [f64; 3],
    /// Motion phase.
    pub motion: Motion,
}

impl From<&BallState> for BallRecord {
    fn from(s: &BallState) -> BallRecord {
        BallRecord {
            pos: [s.pos.x, s.pos.y, s.pos.z],
            vel: [s.vel.x, s.vel.y, s.vel.z],
            spin: [s.spin.x, s.spin.y, s.spin.z],
            motion: s.motion,
        }
    }
}

/// One event (formats.md, plus `cushion`, `pocket`, `normal_speed`, `beyond_rigid_limit`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EventRecord {
    /// Time from the start of the shot, s.
    pub t: f64,
    /// The event's kind by its contract name (`ball_ball`, `slide_to_roll`, ...).
    #[serde(with = "event_kind_name")]
    pub kind: EventKind,
    /// The balls involved, by id.
    pub balls: Vec<String>,
    /// Their states just after the event.
    pub after: OrderedMap<BallRecord>,
    /// The pocket fallen into (`ball_pocket`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pocket: Option<String>,
    /// The cushion nose, jaw or facing met or flown over (`ball_cushion`, `ball_off_table`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cushion: Option<String>,
    /// Approach speed along the contact normal, m/s (impacts).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal_speed: Option<f64>,
    /// A cushion impact faster than the rigid model's limit (thesis §6.2.5).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub beyond_rigid_limit: Option<bool>,
}

/// An event kind by its contract name, both ways.
mod event_kind_name {
    use serde::{Deserialize, Deserializer, Serializer, de};
    use snooker_engine::EventKind;

    pub fn serialize<S: Serializer>(kind: &EventKind, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(kind.name())
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<EventKind, D::Error> {
        let name = String::deserialize(d)?;
        EventKind::from_name(&name)
            .ok_or_else(|| de::Error::custom(format!("unknown event kind `{name}`")))
    }
}

/// A pot: `{ball, pocket, t}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Pot {
    /// The ball potted.
    pub ball: String,
    /// The pocket.
    pub pocket: String,
    /// When it dropped, s.
    pub t: f64,
}

/// A ball that flew off the table: `{ball, cushion, t}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct OffTable {
    /// The ball.
    pub ball: String,
    /// The cushion it flew over.
    pub cushion: String,
    /// When it crossed the nose, s.
    pub t: f64,
}

/// The cue strike as the result reports it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StrikeRecord {
    /// The ball struck.
    pub ball: String,
    /// Cue speed at impact, m/s.
    pub cue_speed: f64,
    /// Contact point relative to the ball's centre, m.
    pub contact: [f64; 3],
    /// Distance of the contact from the line through the ball's centre along the cue, m (the
    /// miscue limit's measure, thesis eq. 7.7).
    pub contact_offset: f64,
    /// Squirt angle, rad (positive: left of the heading).
    pub squirt: f64,
    /// Ball speed over cue speed.
    pub speed_ratio: f64,
    /// The ball's state just after the strike.
    pub after: BallRecord,
    /// The cloth's friction impulse during the strike, N s (an extension: written only when
    /// `mu_strike_cloth` made one; physics.md, "Cue strike").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cloth_friction: Option<[f64; 3]>,
}

/// The result document (formats.md "Result", extended): what `snooker simulate --json`
/// writes, a batch's lines carry and Python reads.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ShotRecord {
    /// The scene's name.
    pub scene: String,
    /// Every event, in time order.
    pub events: Vec<EventRecord>,
    /// Every ball at the end, in the scene's order.
    #[serde(rename = "final")]
    pub final_states: OrderedMap<BallRecord>,
    /// End of the shot, s.
    pub duration: f64,
    /// Why it ended: `at_rest` (every ball at rest or out of play) or `horizon` (stopped at
    /// the scene's `[sim] horizon` with balls still moving, as `final` then shows them).
    #[serde(default = "at_rest")]
    pub ending: snooker_engine::Ending,
    /// Every pot, in time order.
    pub pots: Vec<Pot>,
    /// Every ball that flew off the table, in time order.
    pub off_table: Vec<OffTable>,
    /// The impact models used.
    pub models: Models,
    /// Every parameter used, in their declaration's order.
    pub params: OrderedMap<f64>,
    /// The cue strike, if the scene has one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub strike: Option<StrikeRecord>,
    /// A reminder of the units and frame.
    pub units: String,
}

/// A result document written before `ending` was: every such shot ran to rest.
fn at_rest() -> snooker_engine::Ending {
    snooker_engine::Ending::AtRest
}

/// The result document of `shot`, simulated from `scene`.
pub fn result_record(scene: &Scene, shot: &Shot) -> ShotRecord {
    let ids: Vec<&str> = shot.tracks.iter().map(|t| t.id.as_str()).collect();
    let events = shot
        .events
        .iter()
        .map(|e| {
            let feature = e.feature.clone();
            let (pocket, cushion) = if e.kind == EventKind::BallPocket {
                (feature, None)
            } else {
                (None, feature)
            };
            EventRecord {
                t: e.t,
                kind: e.kind,
                balls: e.balls.iter().map(|&b| ids[b].to_string()).collect(),
                after: OrderedMap(
                    e.balls
                        .iter()
                        .zip(&e.after)
                        .map(|(&b, s)| (ids[b].to_string(), s.into()))
                        .collect(),
                ),
                pocket,
                cushion,
                normal_speed: e.normal_speed,
                beyond_rigid_limit: e
                    .normal_speed
                    .filter(|_| e.kind == EventKind::BallCushion)
                    .map(|v| v > CUSHION_RIGID_LIMIT),
            }
        })
        .collect();
    let final_states = OrderedMap(
        ids.iter()
            .zip(shot.final_states())
            .map(|(id, s)| (id.to_string(), (&s).into()))
            .collect(),
    );
    let pots = departures(shot, EventKind::BallPocket)
        .map(|(ball, pocket, t)| Pot {
            ball: ids[ball].into(),
            pocket: pocket.into(),
            t,
        })
        .collect();
    let off_table = departures(shot, EventKind::BallOffTable)
        .map(|(ball, cushion, t)| OffTable {
            ball: ids[ball].into(),
            cushion: cushion.into(),
            t,
        })
        .collect();
    let params = OrderedMap(
        scene
            .setup
            .params
            .named()
            .iter()
            .map(|(k, v)| (k.to_string(), *v))
            .collect(),
    );
    let strike = scene.strike.as_ref().map(|struck| {
        let s = &struck.strike;
        StrikeRecord {
            ball: struck.id.clone(),
            cue_speed: struck.cue.speed,
            contact: [s.contact.x, s.contact.y, s.contact.z],
            contact_offset: s.contact_offset,
            squirt: s.squirt,
            speed_ratio: s.speed_ratio,
            after: (&s.state).into(),
            cloth_friction: (s.cloth_friction.norm() > 0.0).then(|| {
                let f = s.cloth_friction;
                [f.x, f.y, f.z]
            }),
        }
    });
    ShotRecord {
        scene: scene.name.clone(),
        events,
        final_states,
        duration: shot.duration,
        ending: shot.ending,
        pots,
        off_table,
        models: scene.setup.models,
        params,
        strike,
        units: UNITS.into(),
    }
}

/// The units reminder of every result.
pub const UNITS: &str = "SI: m, s, rad, m/s, rad/s; table frame, z up";

/// A short human summary: events by kind, pots, final positions, simulated duration.
pub fn summary(scene: &Scene, shot: &Shot) -> String {
    let mut out = String::new();
    let m = &scene.setup.models;
    let _ = writeln!(
        out,
        "scene: {}  ({} table; ball-ball model: {}, cushion model: {})",
        scene.name,
        match scene.setup.table.kind {
            snooker_engine::TableKind::Snooker => "snooker",
            snooker_engine::TableKind::Open => "open",
        },
        m.ball_ball.name(),
        m.cushion.name()
    );
    if let Some(struck) = &scene.strike {
        let (ball, cue, s) = (&struck.id, &struck.cue, &struck.strike);
        let _ = writeln!(
            out,
            "strike: {ball} at cue speed {:.3} m/s -> {:.3} m/s, squirt {:.2} deg, contact {:.1} mm off centre across the cue line",
            cue.speed,
            s.state.vel.norm(),
            s.squirt.to_degrees(),
            s.contact_offset * 1e3
        );
    }
    let _ = writeln!(
        out,
        "simulated {:.3} s, {} events{}",
        shot.duration,
        shot.events.len(),
        match shot.ending {
            snooker_engine::Ending::AtRest => " (all balls at rest)",
            snooker_engine::Ending::Horizon => " (stopped at the horizon)",
        }
    );
    let mut by_kind: BTreeMap<&str, usize> = BTreeMap::new();
    for e in &shot.events {
        *by_kind.entry(e.kind.name()).or_default() += 1;
    }
    let kinds: Vec<String> = by_kind.iter().map(|(k, n)| format!("{k} {n}")).collect();
    let _ = writeln!(out, "events by kind: {}", kinds.join(", "));
    let ids: Vec<&str> = shot.tracks.iter().map(|t| t.id.as_str()).collect();
    let listed = |kind: EventKind, word: &str| -> Vec<String> {
        departures(shot, kind)
            .map(|(ball, feature, t)| format!("{} {word} {feature} at {t:.3} s", ids[ball]))
            .collect()
    };
    let pots = listed(EventKind::BallPocket, "in");
    let _ = writeln!(
        out,
        "pots: {}",
        if pots.is_empty() {
            "none".into()
        } else {
            pots.join("; ")
        }
    );
    let off = listed(EventKind::BallOffTable, "over");
    if !off.is_empty() {
        let _ = writeln!(out, "off the table: {}", off.join("; "));
    }
    let _ = writeln!(out, "final positions (x, y in m):");
    for (id, s) in ids.iter().zip(shot.final_states()) {
        let _ = writeln!(
            out,
            "  {id:<8} ({:.4}, {:.4})  {}",
            s.pos.x,
            s.pos.y,
            s.motion.name()
        );
    }
    out
}

/// The balls that left play by events of `kind` (`BallPocket`: the pots; `BallOffTable`):
/// (ball index, pocket or cushion, time).
pub fn departures(shot: &Shot, kind: EventKind) -> impl Iterator<Item = (usize, &str, f64)> {
    shot.events
        .iter()
        .filter(move |e| e.kind == kind)
        .map(|e| (e.balls[0], e.feature.as_deref().unwrap_or("?"), e.t))
}
