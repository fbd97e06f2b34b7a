//! Frame files (formats.md, "Frame"): a scene file plus a `[frame]` table, read through the
//! scene crate (its parser, checks and messages: file, key, reason, line), and written back
//! so that every number reads back to the bit (the referee's next frame).

use crate::colour::Colour;
use crate::error::{FrameError, Key, Problem};
use crate::frame::Frame;
use crate::state::{self, FrameState, On, Scores};
use serde::Deserialize;
use snooker_engine::cue::Cue;
use snooker_engine::{BallKind, Models, Params, SimOptions, SnookerDims};
use snooker_scene::write::num;
use snooker_scene::{Scene, SceneError, WithFrame};
use std::fmt::Write as _;
use std::path::Path;

/// The `[frame]` table as a file gives it.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FrameSpec {
    /// The ball on.
    on: On,
    /// The nominated colour (`""`: none).
    #[serde(default, deserialize_with = "state::deserialize_nominated")]
    nominated: Option<Colour>,
    /// Points of the two players.
    #[serde(default)]
    scores: Scores,
    /// The player at the table.
    #[serde(default)]
    to_play: i64,
    /// The cue ball in hand.
    #[serde(default)]
    ball_in_hand: bool,
    /// Who broke off.
    #[serde(default)]
    first_player: i64,
    /// A free ball awarded.
    #[serde(default)]
    free_ball: bool,
}

/// A frame file read: the frame, its strike (if it has a `[cue]`), and the scene it also is
/// (the strike applied: what the engine simulates, and what the result document describes).
#[derive(Clone, Debug)]
pub struct FrameFile {
    /// The frame before the stroke.
    pub frame: Frame,
    /// The strike, if the file has one.
    pub strike: Option<Cue>,
    /// The file as a scene.
    pub scene: Scene,
    /// The file's name as given.
    pub file: String,
    /// Its text (for the line of a key).
    text: String,
    /// The scene-file key of each ball of the frame.
    ball_keys: Vec<String>,
}

impl FrameFile {
    /// A frame error as this file's error: the key as the file writes it (a listed ball's
    /// `balls[i]`, a layout ball's `layout (ID)`), with its line and column when it has one.
    pub fn locate(&self, e: &FrameError) -> SceneError {
        locate(e, &self.ball_keys, &self.text, &self.file)
    }
}

fn locate(e: &FrameError, ball_keys: &[String], text: &str, file: &str) -> SceneError {
    let key = match &e.key {
        Key::Ball(i, field) => match ball_keys.get(*i) {
            Some(k) if k.starts_with("layout") || field.is_empty() => k.clone(),
            Some(k) => format!("{k}.{field}"),
            None => e.key.to_string(),
        },
        k => k.to_string(),
    };
    let mut reason = e.problem.to_string();
    if let Some((l, c)) = snooker_scene::key_position(text, &key) {
        reason = format!("{reason} (line {l}, column {c})");
    }
    SceneError::new(file, &key, reason)
}

/// Reads a frame file.
pub fn load(path: &Path) -> Result<FrameFile, SceneError> {
    let file = path.display().to_string();
    let text = snooker_scene::read_text(path)
        .map_err(|e| SceneError::new(&file, "", format!("cannot read the frame file: {e}")))?;
    parse(&text, &file)
}

/// Reads frame TOML text; `file` names it in messages.
pub fn parse(text: &str, file: &str) -> Result<FrameFile, SceneError> {
    from_parts(snooker_scene::parse_with_frame(text, file)?, text, file)
}

/// Reads a frame file as a position to choose a stroke from (`snooker play`): its `[cue]`, if
/// any, is read as in any scene but not held to the frame (it may lack the nomination a
/// stroke on a colour needs) and is dropped (`strike` is None).
pub fn load_position(path: &Path) -> Result<FrameFile, SceneError> {
    let file = path.display().to_string();
    let text = snooker_scene::read_text(path)
        .map_err(|e| SceneError::new(&file, "", format!("cannot read the frame file: {e}")))?;
    let mut read = snooker_scene::parse_with_frame(&text, &file)?;
    // The scene holds the strike applied: the struck ball goes back to its state before it.
    if let Some(s) = read.scene.strike.take() {
        read.scene.setup.balls[s.index].state = s.before;
    }
    from_parts(read, &text, &file)
}

/// Reads a frame given as one JSON object with the frame file's keys (a Python dict).
pub fn parse_json(text: &str, file: &str) -> Result<FrameFile, SceneError> {
    from_parts(
        snooker_scene::parse_json_with_frame(text, file)?,
        text,
        file,
    )
}

/// Reads a frame given as a value of any self-describing format with the frame file's keys
/// (a Python dict through pythonize): errors name the key, without a line.
pub fn from_value<'de, D: serde::Deserializer<'de>>(
    d: D,
    file: &str,
) -> Result<FrameFile, SceneError> {
    from_parts(snooker_scene::parse_value_with_frame(d, file)?, "", file)
}

fn player(key: &'static str, v: i64) -> Result<u8, FrameError> {
    u8::try_from(v)
        .ok()
        .filter(|&p| p <= 1)
        .ok_or_else(|| FrameError::new(Key::Frame(key), Problem::NotAPlayer(v)))
}

fn from_parts(read: WithFrame<FrameSpec>, text: &str, file: &str) -> Result<FrameFile, SceneError> {
    let WithFrame {
        scene,
        frame,
        ball_keys,
    } = read;
    let Some(spec) = frame else {
        return Err(SceneError::new(
            file,
            "frame",
            "a frame file needs its [frame] table (on, scores, to_play, ...: formats.md, \"Frame\")",
        ));
    };
    let located = |e: FrameError| locate(&e, &ball_keys, text, file);
    let state = (|| {
        Ok(FrameState {
            on: spec.on,
            nominated: spec.nominated,
            scores: spec.scores.0,
            to_play: player("to_play", spec.to_play)?,
            ball_in_hand: spec.ball_in_hand,
            first_player: player("first_player", spec.first_player)?,
            free_ball: spec.free_ball,
        })
    })()
    .map_err(located)?;
    let mut balls = scene.setup.balls.clone();
    let strike = scene.strike.as_ref().map(|s| {
        balls[s.index].state = s.before;
        (s.index, s.cue)
    });
    let frame = Frame::new(
        scene.name.clone(),
        scene.setup.table.clone(),
        scene.setup.params,
        scene.setup.models,
        scene.options,
        balls,
        state,
    )
    .map_err(&located)?;
    if let Some((index, _)) = strike {
        let struck = &frame.balls()[index];
        if struck.kind != BallKind::Cue {
            return Err(located(FrameError::new(
                Key::Other("cue.ball"),
                Problem::NotTheCueBall(struck.id.clone()),
            )));
        }
        frame.check_ready().map_err(&located)?;
    }
    Ok(FrameFile {
        frame,
        strike: strike.map(|(_, c)| c),
        scene,
        file: file.to_string(),
        text: text.to_string(),
        ball_keys,
    })
}

/// A TOML string literal.
fn quoted(s: &str) -> String {
    toml::Value::String(s.to_string()).to_string()
}

impl Frame {
    /// The frame file of this frame (formats.md, "Frame"), with `strike` as its `[cue]` on
    /// the cue ball if given: every number written to read back to the bit; the table,
    /// parameters, models and limits only where they differ from the defaults.
    pub fn to_toml(&self, strike: Option<&Cue>) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "name = {}", quoted(self.name()));
        let (d, base) = (self.dims(), SnookerDims::default());
        let pockets = [
            ("corner_mouth", d.corner_mouth, base.corner_mouth),
            ("middle_mouth", d.middle_mouth, base.middle_mouth),
            ("jaw_radius", d.jaw_radius, base.jaw_radius),
            ("fall_depth", d.fall_depth, base.fall_depth),
        ];
        if pockets.iter().any(|p| p.1.to_bits() != p.2.to_bits()) {
            let _ = writeln!(s, "[table]\nkind = \"snooker\"");
            for (k, v, _) in pockets {
                let _ = writeln!(s, "{k} = {}", num(v));
            }
        }
        let defaults = Params::default().named();
        let named = self.params().named();
        let radius_given = named
            .iter()
            .zip(&defaults)
            .any(|(a, b)| a.0 == "ball_radius" && a.1.to_bits() != b.1.to_bits());
        let params: Vec<String> = named
            .iter()
            .zip(&defaults)
            .filter(|(a, b)| {
                a.1.to_bits() != b.1.to_bits() || (radius_given && a.0 == "cushion_height")
            })
            .map(|(a, _)| format!("{} = {}", a.0, num(a.1)))
            .collect();
        if !params.is_empty() {
            let _ = writeln!(s, "[params]\n{}", params.join("\n"));
        }
        if *self.models() != Models::default() {
            let m = self.models();
            let _ = writeln!(
                s,
                "[models]\nball_ball = \"{}\"\ncushion = \"{}\"",
                m.ball_ball.name(),
                m.cushion.name()
            );
        }
        let (o, base) = (self.options(), SimOptions::default());
        if o.max_events != base.max_events || o.max_time.to_bits() != base.max_time.to_bits() {
            let _ = writeln!(
                s,
                "[sim]\nmax_events = {}\nmax_time = {}",
                o.max_events,
                num(o.max_time)
            );
        }
        let st = self.state();
        let _ = writeln!(s, "[frame]\non = \"{}\"", st.on);
        if let Some(n) = st.nominated {
            let _ = writeln!(s, "nominated = \"{n}\"");
        }
        let _ = writeln!(
            s,
            "scores = [{}, {}]\nto_play = {}\nball_in_hand = {}\nfirst_player = {}\nfree_ball = {}",
            st.scores[0], st.scores[1], st.to_play, st.ball_in_hand, st.first_player, st.free_ball
        );
        if let (Some(c), Some(i)) = (strike, self.cue_index()) {
            let _ = writeln!(
                s,
                "[cue]\nball = {}\nspeed = {}\naim = {}\noffset = [{}, {}]\nelevation = {}",
                quoted(&self.balls()[i].id),
                num(c.speed),
                num(c.aim),
                num(c.offset[0]),
                num(c.offset[1]),
                num(c.elevation)
            );
        }
        for b in self.balls() {
            let _ = writeln!(
                s,
                "[[balls]]\nid = {}\npos = [{}, {}]",
                quoted(&b.id),
                num(b.state.pos.x),
                num(b.state.pos.y)
            );
            if BallKind::from_id(&b.id) != b.kind {
                let kind = serde_json::to_value(b.kind).ok();
                if let Some(k) = kind.as_ref().and_then(|k| k.as_str()) {
                    let _ = writeln!(s, "kind = \"{k}\"");
                }
            }
        }
        s
    }
}
