//! Scene files (TOML): parsing, defaults and validation, with errors that name the file, the
//! key and the reason. The format is documented in the README and in `shared/formats.md`.

use serde::Deserialize;
use snooker_engine::cue::{self, Cue, Strike};
use snooker_engine::table::layout;
use snooker_engine::{
    Ball, BallBallModel, BallKind, BallState, CushionModel, Models, Params, Setup, SimOptions,
    SnookerDims, Table, TableKind, Vec3,
};
use std::path::Path;

/// The scene `snooker simulate` runs when given none.
pub const DEFAULT_SCENE: &str = include_str!("../scenes/break-off.toml");
/// The name shown for the built-in default scene.
pub const DEFAULT_SCENE_FILE: &str = "scenes/break-off.toml (built in)";

/// A scene that cannot be used: which file, which key, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError {
    /// The file (as given by the user).
    pub file: String,
    /// The key at fault, dotted (`balls[2].pos`), or empty when the file itself is at fault.
    pub key: String,
    /// Why.
    pub reason: String,
}

impl std::fmt::Display for SceneError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.key.is_empty() {
            write!(f, "{}: {}", self.file, self.reason)
        } else {
            write!(f, "{}: key `{}`: {}", self.file, self.key, self.reason)
        }
    }
}

impl std::error::Error for SceneError {}

/// A loaded, validated scene.
#[derive(Debug, Clone)]
pub struct Scene {
    /// Free-text name.
    pub name: String,
    /// What the engine simulates (the cue strike already applied).
    pub setup: Setup,
    /// Limits of the simulation.
    pub options: SimOptions,
    /// The cue strike, if the scene has one: which ball and what it did.
    pub strike: Option<(String, Cue, Strike)>,
    /// The struck ball's state before the strike.
    pub before_strike: Option<BallState>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    name: Option<String>,
    #[serde(default)]
    table: TableSpec,
    #[serde(default)]
    params: ParamSpec,
    #[serde(default)]
    models: ModelSpec,
    layout: Option<String>,
    #[serde(default)]
    balls: Vec<BallSpec>,
    cue: Option<CueSpec>,
    #[serde(default)]
    sim: SimSpec,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct TableSpec {
    #[serde(default)]
    kind: TableKind,
    corner_mouth: Option<f64>,
    middle_mouth: Option<f64>,
    jaw_radius: Option<f64>,
    fall_depth: Option<f64>,
}

macro_rules! param_spec {
    ($($name:ident),* $(,)?) => {
        #[derive(Deserialize, Default)]
        #[serde(deny_unknown_fields)]
        struct ParamSpec {
            $($name: Option<f64>,)*
        }

        impl ParamSpec {
            /// Defaults overridden by the values given.
            fn apply(&self) -> Params {
                self.apply_to(Params::default())
            }

            /// `base` overridden by the values given.
            fn apply_to(&self, base: Params) -> Params {
                let mut p = base;
                if let Some(r) = self.ball_radius {
                    // The nose height follows the ball unless given: h = 7R/5 (thesis §6.2).
                    p.cushion_height = 1.4 * r;
                }
                $(if let Some(v) = self.$name { p.$name = v; })*
                p
            }
        }
    };
}

param_spec!(
    g,
    ball_mass,
    ball_radius,
    mu_slide,
    mu_roll,
    sidespin_decel,
    e_ball,
    mu_ball,
    e_cushion,
    mu_cushion,
    cushion_height,
    cue_mass,
    cue_tip_radius,
    cue_tip_restitution,
    cue_endmass,
    miscue_limit,
    slope_x,
    slope_y,
    nap_drift,
    mu_slide_low,
    slide_speed_scale,
    e_cushion_falloff,
    e_cushion_knee,
);

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct ModelSpec {
    ball_ball: Option<BallBallModel>,
    cushion: Option<CushionModel>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BallSpec {
    id: String,
    pos: [f64; 2],
    vel: Option<[f64; 3]>,
    spin: Option<[f64; 3]>,
    kind: Option<BallKind>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CueSpec {
    ball: String,
    speed: f64,
    aim: f64,
    #[serde(default)]
    offset: [f64; 2],
    #[serde(default)]
    elevation: f64,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct SimSpec {
    max_events: Option<usize>,
    max_time: Option<f64>,
    horizon: Option<f64>,
}

/// Reads and validates a scene file.
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| SceneError {
        file: file.clone(),
        key: String::new(),
        reason: format!("cannot read the scene file: {e}"),
    })?;
    parse(&text, &file)
}

/// 1-based line and column of byte `offset` in `text`.
fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

/// Deserializes TOML `text` into `T`, with errors naming `file`, the key, line and column.
/// Shared by every TOML input of the command line (scenes, models, measured data).
pub fn from_toml<T: serde::de::DeserializeOwned>(text: &str, file: &str) -> Result<T, SceneError> {
    let fail = |key: &str, reason: String| SceneError {
        file: file.to_string(),
        key: key.to_string(),
        reason,
    };
    let de = toml::de::Deserializer::parse(text).map_err(|e| {
        let at = e.span().map(|s| line_col(text, s.start));
        let reason = match at {
            Some((l, c)) => format!("not valid TOML (line {l}, column {c}): {}", e.message()),
            None => format!("not valid TOML: {}", e.message()),
        };
        fail("", reason)
    })?;
    serde_path_to_error::deserialize(de).map_err(|e| {
        let key = e.path().to_string();
        let inner = e.into_inner();
        let mut reason = inner.message().trim().to_string();
        if let Some((l, c)) = inner.span().map(|s| line_col(text, s.start)) {
            reason = format!("{reason} (line {l}, column {c})");
        }
        fail(if key == "." { "" } else { &key }, reason)
    })
}

/// Parses and validates scene text; `file` names it in error messages.
pub fn parse(text: &str, file: &str) -> Result<Scene, SceneError> {
    build(from_toml(text, file)?, file)
}

/// Applies `NAME=VALUE` overrides (`--param` on the command line, the scene files' names) to
/// `base`, then validates the result. As in a scene, the nose height follows a new ball
/// radius unless given too (h = 7R/5, thesis §6.2).
pub fn override_params(base: Params, overrides: &[String]) -> anyhow::Result<Params> {
    use anyhow::Context;
    let mut p = base;
    let given = |n: &str| {
        overrides
            .iter()
            .any(|x| x.split_once('=').is_some_and(|(k, _)| k.trim() == n))
    };
    for o in overrides {
        let (name, value) = o
            .split_once('=')
            .with_context(|| format!("--param {o}: expected NAME=VALUE"))?;
        let v: f64 = value
            .trim()
            .parse()
            .with_context(|| format!("--param {o}: {value} is not a number"))?;
        let slot = p.field_mut(name.trim()).with_context(|| {
            format!(
                "--param {o}: unknown parameter `{}` (one of {})",
                name.trim(),
                Params::default().named().map(|e| e.0).join(", ")
            )
        })?;
        *slot = v;
    }
    if given("ball_radius") && !given("cushion_height") {
        p.cushion_height = 1.4 * p.ball_radius;
    }
    p.validate().map_err(|e| anyhow::anyhow!("--param {e}"))?;
    Ok(p)
}

/// A model file: `[params]` and `[models]` tables as in a scene, nothing else.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct ModelFile {
    #[serde(default)]
    params: ParamSpec,
    #[serde(default)]
    models: ModelSpec,
}

/// Parses a model file (TOML with `[params]` and `[models]` as in a scene) and applies it on
/// top of `params` and `models`; `file` names it in error messages.
pub fn parse_model(
    text: &str,
    file: &str,
    params: Params,
    models: Models,
) -> Result<(Params, Models), SceneError> {
    let spec: ModelFile = from_toml(text, file)?;
    let p = spec.params.apply_to(params);
    p.validate().map_err(|e| SceneError {
        file: file.to_string(),
        key: format!("params.{}", e.name),
        reason: e.reason,
    })?;
    let m = Models {
        ball_ball: spec.models.ball_ball.unwrap_or(models.ball_ball),
        cushion: spec.models.cushion.unwrap_or(models.cushion),
    };
    Ok((p, m))
}

fn check_finite(key: &str, values: &[f64], file: &str) -> Result<(), SceneError> {
    if let Some(v) = values.iter().find(|v| !v.is_finite()) {
        return Err(SceneError {
            file: file.to_string(),
            key: key.to_string(),
            reason: format!("must be a finite number, got {v}"),
        });
    }
    Ok(())
}

fn build(spec: SceneFile, file: &str) -> Result<Scene, SceneError> {
    let fail = |key: &str, reason: String| SceneError {
        file: file.to_string(),
        key: key.to_string(),
        reason,
    };
    let params = spec.params.apply();
    params
        .validate()
        .map_err(|e| fail(&format!("params.{}", e.name), e.reason))?;

    let mut dims = SnookerDims::default();
    for (key, given, slot) in [
        (
            "table.corner_mouth",
            spec.table.corner_mouth,
            &mut dims.corner_mouth,
        ),
        (
            "table.middle_mouth",
            spec.table.middle_mouth,
            &mut dims.middle_mouth,
        ),
        (
            "table.jaw_radius",
            spec.table.jaw_radius,
            &mut dims.jaw_radius,
        ),
        (
            "table.fall_depth",
            spec.table.fall_depth,
            &mut dims.fall_depth,
        ),
    ] {
        if let Some(v) = given {
            check_finite(key, &[v], file)?;
            if !(0.0..=0.5).contains(&v) {
                return Err(fail(key, format!("must lie in [0, 0.5] m, got {v}")));
            }
            *slot = v;
        }
    }
    if dims.corner_mouth < 2.0 * params.ball_radius || dims.middle_mouth < 2.0 * params.ball_radius
    {
        return Err(fail(
            "table",
            "a pocket opening narrower than a ball could never take one".into(),
        ));
    }
    let table = match spec.table.kind {
        TableKind::Snooker => Table::snooker(&dims),
        TableKind::Open => {
            if spec.table.corner_mouth.is_some()
                || spec.table.middle_mouth.is_some()
                || spec.table.jaw_radius.is_some()
                || spec.table.fall_depth.is_some()
            {
                return Err(fail(
                    "table",
                    "the open table has no pockets to size".into(),
                ));
            }
            Table::open()
        }
    };

    let r = params.ball_radius;
    let mut balls: Vec<Ball> = match &spec.layout {
        None => Vec::new(),
        Some(name) => {
            if table.kind != TableKind::Snooker {
                return Err(fail(
                    "layout",
                    format!("layout \"{name}\" needs the snooker table"),
                ));
            }
            layout::by_name(name, &dims, r).ok_or_else(|| {
                fail(
                    "layout",
                    format!(
                        "unknown layout \"{name}\"; known: {}",
                        layout::LAYOUTS.join(", ")
                    ),
                )
            })?
        }
    };
    // Keys of the scene file for each ball: listed balls override layout balls of the same id.
    let mut keys: Vec<String> = balls.iter().map(|_| "layout".to_string()).collect();
    for (i, b) in spec.balls.iter().enumerate() {
        let key = format!("balls[{i}]");
        check_finite(&format!("{key}.pos"), &b.pos, file)?;
        check_finite(&format!("{key}.vel"), &b.vel.unwrap_or_default(), file)?;
        check_finite(&format!("{key}.spin"), &b.spin.unwrap_or_default(), file)?;
        if b.id.trim().is_empty() {
            return Err(fail(
                &format!("{key}.id"),
                "a ball needs a non-empty id".into(),
            ));
        }
        if spec.balls[..i].iter().any(|o| o.id == b.id) {
            return Err(fail(
                &format!("{key}.id"),
                format!("ball id \"{}\" is used twice", b.id),
            ));
        }
        let state = BallState {
            pos: Vec3::new(b.pos[0], b.pos[1], r),
            vel: Vec3::from(b.vel.unwrap_or_default()),
            spin: Vec3::from(b.spin.unwrap_or_default()),
            motion: snooker_engine::Motion::Stationary,
        };
        let ball = Ball {
            id: b.id.clone(),
            kind: b.kind.unwrap_or_else(|| BallKind::from_id(&b.id)),
            state,
        };
        match balls.iter().position(|o| o.id == b.id) {
            Some(j) => {
                balls[j] = ball;
                keys[j] = key;
            }
            None => {
                balls.push(ball);
                keys.push(key);
            }
        }
    }
    if balls.is_empty() {
        return Err(fail(
            "balls",
            "the scene has no balls (list [[balls]] or name a layout)".into(),
        ));
    }

    let mut strike = None;
    let mut before_strike = None;
    if let Some(c) = &spec.cue {
        let Some(i) = balls.iter().position(|b| b.id == c.ball) else {
            return Err(fail(
                "cue.ball",
                format!("no ball with id \"{}\" in the scene", c.ball),
            ));
        };
        let cue = Cue {
            speed: c.speed,
            aim: c.aim,
            offset: c.offset,
            elevation: c.elevation,
        };
        let s = cue::strike(&balls[i].state, &cue, &params)
            .map_err(|e| fail(&format!("cue.{}", e.key), e.reason))?;
        before_strike = Some(balls[i].state);
        balls[i].state = s.state;
        strike = Some((c.ball.clone(), cue, s));
    }

    let mut options = SimOptions::default();
    if let Some(n) = spec.sim.max_events {
        if n == 0 {
            return Err(fail("sim.max_events", "must be at least 1".into()));
        }
        options.max_events = n;
    }
    for (key, v, slot) in [("sim.max_time", spec.sim.max_time, &mut options.max_time)] {
        if let Some(v) = v {
            if !(v.is_finite() && v > 0.0) {
                return Err(fail(
                    key,
                    format!("must be a positive number of seconds, got {v}"),
                ));
            }
            *slot = v;
        }
    }
    if let Some(h) = spec.sim.horizon {
        if !(h.is_finite() && h > 0.0) {
            return Err(fail(
                "sim.horizon",
                format!("must be a positive number of seconds, got {h}"),
            ));
        }
        options.horizon = Some(h);
    }

    let setup = Setup {
        table,
        params,
        models: Models {
            ball_ball: spec.models.ball_ball.unwrap_or_default(),
            cushion: spec.models.cushion.unwrap_or_default(),
        },
        balls,
    };
    setup.validate().map_err(|e| match e.ball {
        Some(i) => {
            let key = &keys[i];
            let key = if key == "layout" {
                format!("layout ({})", setup.balls[i].id)
            } else {
                format!("{key}.{}", e.field)
            };
            fail(&key, e.reason)
        }
        None => fail(&e.field, e.reason),
    })?;
    Ok(Scene {
        name: spec.name.unwrap_or_else(|| {
            Path::new(file)
                .file_stem()
                .map_or("scene".into(), |s| s.to_string_lossy().into_owned())
        }),
        setup,
        options,
        strike,
        before_strike,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> SceneError {
        parse(text, "t.toml").unwrap_err()
    }

    #[test]
    fn default_scene_loads() {
        let s = parse(DEFAULT_SCENE, "break-off.toml").unwrap();
        assert_eq!(s.setup.balls.len(), 22);
        assert!(s.strike.is_some());
    }

    #[test]
    fn errors_name_the_key() {
        let e = err("[params]\nmu_slid = 0.2\n");
        assert_eq!(e.key, "params.mu_slid");
        assert!(e.reason.contains("mu_slid"), "{e}");
        let e = err("[[balls]]\nid = \"a\"\npos = [0.5, nan]\n");
        assert_eq!(e.key, "balls[0].pos");
        let e = err(
            "[[balls]]\nid = \"a\"\npos = [0.5, 0.5]\n[[balls]]\nid = \"b\"\npos = [0.51, 0.5]\n",
        );
        assert_eq!(e.key, "balls[1].pos");
        assert!(e.reason.contains("overlaps"));
        let e = err("[[balls]]\nid = \"a\"\npos = [5.0, 0.5]\n");
        assert!(e.reason.contains("off the cloth"), "{e}");
        let e = err(
            "[[balls]]\nid = \"a\"\npos = [0.5, 0.5]\n[cue]\nball = \"a\"\nspeed = 2\naim = 0\noffset = [0.02, 0]\n",
        );
        assert_eq!(e.key, "cue.offset");
        assert!(e.reason.contains("miscue"));
        let e = err("[models]\nball_ball = \"magic\"\n");
        assert_eq!(e.key, "models.ball_ball");
        let e = err("name = \n");
        assert!(e.reason.contains("line 1"), "{e}");
    }
}
