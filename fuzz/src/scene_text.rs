//! A scene being generated, written out as scene-file TOML (the format of `shared/formats.md`):
//! what the fuzz harness feeds the parser, and what it writes for every failing scene.

use std::fmt::Write as _;

/// A ball of a generated scene.
#[derive(Clone, Debug)]
pub struct BallText {
    /// Its id.
    pub id: String,
    /// Centre [x, y], m.
    pub pos: [f64; 2],
    /// Velocity, m/s.
    pub vel: Option<[f64; 3]>,
    /// Angular velocity, rad/s.
    pub spin: Option<[f64; 3]>,
}

/// A cue strike of a generated scene.
#[derive(Clone, Copy, Debug)]
pub struct CueText {
    /// Cue speed, m/s.
    pub speed: f64,
    /// Heading, rad.
    pub aim: f64,
    /// [side, height], m.
    pub offset: [f64; 2],
    /// Elevation, rad.
    pub elevation: f64,
}

/// A generated scene.
#[derive(Clone, Debug, Default)]
pub struct SceneText {
    /// The open table instead of the snooker table.
    pub open_table: bool,
    /// A named layout.
    pub layout: Option<String>,
    /// Parameters set, by name.
    pub params: Vec<(&'static str, f64)>,
    /// Impact models (ball-ball, cushion).
    pub models: Option<(&'static str, &'static str)>,
    /// Balls listed.
    pub balls: Vec<BallText>,
    /// The strike, on the first ball (or "cue").
    pub cue: Option<(String, CueText)>,
}

/// A number as TOML reads it back exactly (Rust's shortest round-trip form).
pub fn num(v: f64) -> String {
    if v.is_nan() {
        "nan".into()
    } else if v.is_infinite() {
        if v > 0.0 { "inf".into() } else { "-inf".into() }
    } else {
        format!("{v:?}")
    }
}

fn array(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(|&x| num(x)).collect();
    format!("[{}]", parts.join(", "))
}

impl SceneText {
    /// The scene file.
    pub fn to_toml(&self) -> String {
        let mut s = String::new();
        if let Some(l) = &self.layout {
            let _ = writeln!(s, "layout = \"{l}\"");
        }
        if self.open_table {
            let _ = writeln!(s, "[table]\nkind = \"open\"");
        }
        if !self.params.is_empty() {
            let _ = writeln!(s, "[params]");
            for (k, v) in &self.params {
                let _ = writeln!(s, "{k} = {}", num(*v));
            }
        }
        if let Some((bb, c)) = self.models {
            let _ = writeln!(s, "[models]\nball_ball = \"{bb}\"\ncushion = \"{c}\"");
        }
        if let Some((ball, c)) = &self.cue {
            let _ = writeln!(
                s,
                "[cue]\nball = \"{ball}\"\nspeed = {}\naim = {}\noffset = {}\nelevation = {}",
                num(c.speed),
                num(c.aim),
                array(&c.offset),
                num(c.elevation)
            );
        }
        for b in &self.balls {
            let _ = writeln!(s, "[[balls]]\nid = \"{}\"\npos = {}", b.id, array(&b.pos));
            if let Some(v) = b.vel {
                let _ = writeln!(s, "vel = {}", array(&v));
            }
            if let Some(w) = b.spin {
                let _ = writeln!(s, "spin = {}", array(&w));
            }
        }
        s
    }
}
