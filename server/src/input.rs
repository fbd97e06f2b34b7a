//! Scenes and frames as the page sends them: one JSON object with the scene file's keys (a
//! frame: the frame file's, `frame` included), read and checked by the scene and rules crates
//! exactly as a file is (the same messages, the key at fault), then held to the server's
//! [`Limits`]. TOML text (a file uploaded or pasted) is read by the same parsers. What goes
//! back to the page is the same kind of object with every ball listed (a layout expanded),
//! so that the page can move any ball.

use crate::error::ApiError;
use crate::limits::Limits;
use serde::de::IgnoredAny;
use serde_json::Value;
use snooker_engine::{BallKind, SimOptions};
use snooker_rules::file::FrameFile;
use snooker_scene::{BallSpec, Scene, SceneFile};

/// The name the API's errors give a scene in a request.
pub const SCENE: &str = "scene";
/// The name the API's errors give a frame in a request.
pub const FRAME: &str = "frame";

/// A scene read and checked: what the engine simulates, and its file with every ball listed.
#[derive(Debug, Clone)]
pub struct CheckedScene {
    /// The scene (the strike applied, the simulation limits held to the server's).
    pub scene: Scene,
    /// The scene file: every ball listed where it lies before the strike, no layout.
    pub file: SceneFile,
}

/// Holds a scene's simulation to the server's limits: the event cap and the simulated time
/// are lowered to the server's when the scene asks for more (the scene's own smaller limits
/// are kept).
pub fn bounded(options: SimOptions, limits: &Limits) -> SimOptions {
    SimOptions {
        max_events: options.max_events.min(limits.events),
        max_time: options.max_time.min(limits.sim_time),
        horizon: options.horizon.map(|h| h.min(limits.sim_time)),
        ..options
    }
}

fn ball_count(n: usize, file: &str, limits: &Limits) -> Result<(), ApiError> {
    if n > limits.balls {
        return Err(ApiError::bad(
            file,
            "balls",
            format!(
                "{n} balls: the server takes at most {} in a scene",
                limits.balls
            ),
        ));
    }
    Ok(())
}

/// The scene file of `scene` read from `spec` with every ball listed: balls of a layout are
/// written out where they lie, listed balls are kept as given, the struck ball where it was
/// before the strike.
fn expanded<X>(mut spec: SceneFile<X>, scene: &Scene, keys: &[String]) -> SceneFile {
    let listed = std::mem::take(&mut spec.balls);
    let balls = scene
        .setup
        .balls
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let from_list = keys[i]
                .strip_prefix("balls[")
                .and_then(|k| k.strip_suffix(']'))
                .and_then(|k| k.parse::<usize>().ok())
                .and_then(|k| listed.get(k));
            match from_list {
                Some(spec) => spec.clone(),
                None => {
                    let mut spec = BallSpec::at(b.id.clone(), [b.state.pos.x, b.state.pos.y]);
                    if BallKind::from_id(&b.id) != b.kind {
                        spec.kind = Some(b.kind);
                    }
                    spec
                }
            }
        })
        .collect();
    SceneFile {
        name: spec.name,
        table: spec.table,
        params: spec.params,
        models: spec.models,
        layout: None,
        balls,
        cue: spec.cue,
        sim: spec.sim,
        frame: None,
    }
}

/// Reads a scene given as a JSON object with the scene file's keys (a `frame` table is not
/// read, as `snooker simulate` does not read it).
pub fn scene(value: &Value, limits: &Limits) -> Result<CheckedScene, ApiError> {
    object(value, SCENE)?;
    let spec: SceneFile<IgnoredAny> = snooker_scene::from_value(value, SCENE)?;
    finish(spec, SCENE, limits)
}

/// Reads a scene given as TOML text (a scene file uploaded or pasted): `snooker simulate`'s
/// parser, the file named `file`.
pub fn scene_toml(text: &str, file: &str, limits: &Limits) -> Result<CheckedScene, ApiError> {
    let spec: SceneFile<IgnoredAny> = snooker_scene::from_toml(text, file)?;
    finish(spec, file, limits)
}

fn finish(
    spec: SceneFile<IgnoredAny>,
    file: &str,
    limits: &Limits,
) -> Result<CheckedScene, ApiError> {
    let (mut scene, keys) = snooker_scene::build::build_keyed(spec.clone(), file)?;
    ball_count(scene.setup.balls.len(), file, limits)?;
    scene.options = bounded(scene.options, limits);
    let file = expanded(spec, &scene, &keys);
    Ok(CheckedScene { scene, file })
}

/// Reads a frame given as a JSON object with the frame file's keys (`snooker referee`'s
/// reader, as Python's dicts are read).
pub fn frame(value: &Value, limits: &Limits) -> Result<FrameFile, ApiError> {
    object(value, FRAME)?;
    let f = snooker_rules::from_value(value, FRAME)?;
    frame_bounded(f, FRAME, limits)
}

/// A scene or frame is an object of the file's keys: an array would be read by position.
fn object(value: &Value, file: &str) -> Result<(), ApiError> {
    if value.is_object() {
        Ok(())
    } else {
        Err(ApiError::bad(
            file,
            "",
            format!("a {file} is a JSON object with the file's keys"),
        ))
    }
}

/// Holds a frame read to the server's limits: its balls counted, its simulations (the scene's
/// and the frame's own, which every stroke the player tries is simulated with) bounded.
fn frame_bounded(mut f: FrameFile, file: &str, limits: &Limits) -> Result<FrameFile, ApiError> {
    ball_count(f.scene.setup.balls.len(), file, limits)?;
    f.scene.options = bounded(f.scene.options, limits);
    let options = bounded(*f.frame.options(), limits);
    if options != *f.frame.options() {
        let g = &f.frame;
        f.frame = snooker_rules::Frame::new(
            g.name(),
            g.table().clone(),
            *g.params(),
            *g.models(),
            options,
            g.balls().to_vec(),
            *g.state(),
        )
        .map_err(|e| ApiError::from(f.locate(&e)))?;
    }
    Ok(f)
}

/// Reads a frame given as TOML text (a frame file, or a play log line's `frame`).
pub fn frame_toml(text: &str, file: &str, limits: &Limits) -> Result<FrameFile, ApiError> {
    let f = snooker_rules::parse(text, file)?;
    frame_bounded(f, file, limits)
}

/// A frame as the page holds it: the frame file's keys as one JSON object (the file
/// [`snooker_rules::Frame::to_toml`] writes, read as TOML and given as JSON: every number the
/// same bits).
pub fn frame_value(
    frame: &snooker_rules::Frame,
    strike: Option<&snooker_engine::Cue>,
) -> Result<Value, ApiError> {
    let text = frame.to_toml(strike);
    let table: toml::Table = toml::from_str(&text)
        .map_err(|e| ApiError::internal(format!("the frame written does not read back: {e}")))?;
    serde_json::to_value(table).map_err(|e| ApiError::internal(e.to_string()))
}

/// A scene file as the page holds it.
pub fn scene_value(file: &SceneFile) -> Result<Value, ApiError> {
    serde_json::to_value(file).map_err(|e| ApiError::internal(e.to_string()))
}
