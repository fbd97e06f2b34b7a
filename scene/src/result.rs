//! The JSON result of a shot (the contract in `shared/formats.md`; extended, never renamed) and
//! the human summary printed by `snooker simulate`.

use crate::Scene;
use serde_json::{Map, Value, json};
use snooker_engine::{BallState, EventKind, Shot};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// Normal impact speed above which the thesis's rigid cushion model is not valid, m/s
/// (thesis §5.1.2, §6.2.5: the cushion deforms; data file `rigid_limit_speed`).
pub const CUSHION_RIGID_LIMIT: f64 = 2.5;

fn state_json(s: &BallState) -> Value {
    json!({
        "pos": [s.pos.x, s.pos.y, s.pos.z],
        "vel": [s.vel.x, s.vel.y, s.vel.z],
        "spin": [s.spin.x, s.spin.y, s.spin.z],
        "motion": s.motion.name(),
    })
}

/// The result document: `scene`, `events`, `final`, plus documented extensions.
pub fn result_json(scene: &Scene, shot: &Shot) -> Value {
    let ids: Vec<&str> = shot.tracks.iter().map(|t| t.id.as_str()).collect();
    let events: Vec<Value> = shot
        .events
        .iter()
        .map(|e| {
            let mut after = Map::new();
            for (&b, s) in e.balls.iter().zip(&e.after) {
                after.insert(ids[b].to_string(), state_json(s));
            }
            let mut ev = Map::new();
            ev.insert("t".into(), json!(e.t));
            ev.insert("kind".into(), json!(e.kind.name()));
            ev.insert(
                "balls".into(),
                json!(e.balls.iter().map(|&b| ids[b]).collect::<Vec<_>>()),
            );
            ev.insert("after".into(), Value::Object(after));
            if let Some(f) = &e.feature {
                let key = if e.kind == EventKind::BallPocket {
                    "pocket"
                } else {
                    "cushion"
                };
                ev.insert(key.into(), json!(f));
            }
            if let Some(v) = e.normal_speed {
                ev.insert("normal_speed".into(), json!(v));
                if e.kind == EventKind::BallCushion {
                    ev.insert("beyond_rigid_limit".into(), json!(v > CUSHION_RIGID_LIMIT));
                }
            }
            Value::Object(ev)
        })
        .collect();
    let mut fin = Map::new();
    for (id, s) in ids.iter().zip(shot.final_states()) {
        fin.insert(id.to_string(), state_json(&s));
    }
    // Balls leaving play: {ball, pocket or cushion, t}.
    let departures = |kind: EventKind, key: &str| -> Vec<Value> {
        departures(shot, kind)
            .map(|(ball, feature, t)| json!({"ball": ids[ball], key: feature, "t": t}))
            .collect()
    };
    let pots = departures(EventKind::BallPocket, "pocket");
    let off_table = departures(EventKind::BallOffTable, "cushion");
    let mut doc = Map::new();
    doc.insert("scene".into(), json!(scene.name));
    doc.insert("events".into(), Value::Array(events));
    doc.insert("final".into(), Value::Object(fin));
    doc.insert("duration".into(), json!(shot.duration));
    doc.insert("pots".into(), Value::Array(pots));
    doc.insert("off_table".into(), Value::Array(off_table));
    doc.insert(
        "models".into(),
        json!({
            "ball_ball": scene.setup.models.ball_ball.name(),
            "cushion": scene.setup.models.cushion.name(),
        }),
    );
    let params: Map<String, Value> = scene
        .setup
        .params
        .named()
        .iter()
        .map(|(k, v)| (k.to_string(), json!(v)))
        .collect();
    doc.insert("params".into(), Value::Object(params));
    if let Some(struck) = &scene.strike {
        let (ball, cue, s) = (&struck.id, &struck.cue, &struck.strike);
        doc.insert(
            "strike".into(),
            json!({
                "ball": ball,
                "cue_speed": cue.speed,
                "contact": [s.contact.x, s.contact.y, s.contact.z],
                "contact_offset": s.contact_offset,
                "squirt": s.squirt,
                "speed_ratio": s.speed_ratio,
                "after": state_json(&s.state),
            }),
        );
    }
    doc.insert(
        "units".into(),
        json!("SI: m, s, rad, m/s, rad/s; table frame, z up"),
    );
    Value::Object(doc)
}

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
            "strike: {ball} at cue speed {:.3} m/s -> {:.3} m/s, squirt {:.2} deg, contact {:.1} mm off the cue axis",
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
