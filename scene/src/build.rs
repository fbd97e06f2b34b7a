//! A parsed scene file turned into what the engine simulates: parameters, table, balls (layout
//! and listed), the cue strike applied, and the limits; every value checked against its range
//! with an error naming the key.

use crate::file::SceneFile;
use crate::{Scene, SceneError, StruckBall};
use snooker_engine::cue::Cue;
use snooker_engine::shown::Shown;
use snooker_engine::table::layout;
use snooker_engine::{
    Ball, BallKind, BallState, Motion, Params, Setup, SimOptions, SnookerDims, Table, TableKind,
    Vec3,
};
use std::path::Path;

/// Longest simulated time a scene may ask for, s (`[sim] max_time`, `horizon`): a day.
pub const MAX_SIM_TIME: f64 = 86_400.0;
/// Largest pocket opening, jaw radius or fall depth, m.
pub const MAX_POCKET_SIZE: f64 = 0.5;

fn check_finite(file: &str, key: &str, values: &[f64]) -> Result<(), SceneError> {
    match values.iter().find(|v| !v.is_finite()) {
        Some(v) => Err(SceneError::new(
            file,
            key,
            format!("must be a finite number, got {v}"),
        )),
        None => Ok(()),
    }
}

/// The table of `spec`, its pocket sizes checked against the ball radius `r`.
fn table<X>(spec: &SceneFile<X>, r: f64, file: &str) -> Result<(Table, SnookerDims), SceneError> {
    let fail = |key: &str, reason: String| SceneError::new(file, key, reason);
    let t = &spec.table;
    let mut dims = SnookerDims::default();
    for (key, given, slot) in [
        ("table.corner_mouth", t.corner_mouth, &mut dims.corner_mouth),
        ("table.middle_mouth", t.middle_mouth, &mut dims.middle_mouth),
        ("table.jaw_radius", t.jaw_radius, &mut dims.jaw_radius),
        ("table.fall_depth", t.fall_depth, &mut dims.fall_depth),
    ] {
        if let Some(v) = given {
            check_finite(file, key, &[v])?;
            if !(0.0..=MAX_POCKET_SIZE).contains(&v) {
                return Err(fail(
                    key,
                    format!("must lie in [0, {MAX_POCKET_SIZE}] m, got {}", Shown(v)),
                ));
            }
            *slot = v;
        }
    }
    if dims.corner_mouth < 2.0 * r || dims.middle_mouth < 2.0 * r {
        return Err(fail(
            "table",
            "a pocket opening narrower than a ball could never take one".into(),
        ));
    }
    let table = match t.kind {
        TableKind::Snooker => Table::snooker(&dims),
        TableKind::Open => {
            let sized = [t.corner_mouth, t.middle_mouth, t.jaw_radius, t.fall_depth];
            if sized.iter().any(Option::is_some) {
                return Err(fail(
                    "table",
                    "the open table has no pockets to size".into(),
                ));
            }
            Table::open()
        }
    };
    Ok((table, dims))
}

/// The balls of `spec` (layout first, listed balls replacing layout balls of the same id) and
/// the scene-file key of each.
fn balls<X>(
    spec: &SceneFile<X>,
    table: &Table,
    dims: &SnookerDims,
    r: f64,
    file: &str,
) -> Result<(Vec<Ball>, Vec<String>), SceneError> {
    let fail = |key: &str, reason: String| SceneError::new(file, key, reason);
    let mut balls: Vec<Ball> = match &spec.layout {
        None => Vec::new(),
        Some(name) => {
            if table.kind != TableKind::Snooker {
                return Err(fail(
                    "layout",
                    format!("layout \"{name}\" needs the snooker table"),
                ));
            }
            layout::by_name(name, dims, r).ok_or_else(|| {
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
    let mut keys: Vec<String> = balls.iter().map(|_| "layout".to_string()).collect();
    for (i, b) in spec.balls.iter().enumerate() {
        let key = format!("balls[{i}]");
        let vel = b.vel.unwrap_or_default().0;
        let spin = b.spin.unwrap_or_default().0;
        check_finite(file, &format!("{key}.pos"), &b.pos.0)?;
        check_finite(file, &format!("{key}.vel"), &vel)?;
        check_finite(file, &format!("{key}.spin"), &spin)?;
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
        let ball = Ball {
            id: b.id.clone(),
            kind: b.kind.unwrap_or_else(|| BallKind::from_id(&b.id)),
            state: BallState {
                pos: Vec3::new(b.pos.0[0], b.pos.0[1], r),
                vel: Vec3::from(vel),
                spin: Vec3::from(spin),
                motion: Motion::Stationary,
            },
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
    Ok((balls, keys))
}

/// The limits of `[sim]`.
fn options<X>(spec: &SceneFile<X>, file: &str) -> Result<SimOptions, SceneError> {
    let fail = |key: &str, reason: String| SceneError::new(file, key, reason);
    let mut options = SimOptions::default();
    if let Some(n) = spec.sim.max_events {
        if n == 0 {
            return Err(fail("sim.max_events", "must be at least 1".into()));
        }
        options.max_events = n;
    }
    let seconds = |key: &str, v: f64| {
        if v.is_finite() && v > 0.0 && v <= MAX_SIM_TIME {
            Ok(v)
        } else {
            Err(fail(
                key,
                format!(
                    "must be a number of seconds in (0, {MAX_SIM_TIME}], got {}",
                    Shown(v)
                ),
            ))
        }
    };
    if let Some(v) = spec.sim.max_time {
        options.max_time = seconds("sim.max_time", v)?;
    }
    if let Some(h) = spec.sim.horizon {
        options.horizon = Some(seconds("sim.horizon", h)?);
    }
    Ok(options)
}

/// Builds and validates the scene of `spec`; `file` names it in errors.
pub fn build(spec: SceneFile, file: &str) -> Result<Scene, SceneError> {
    build_keyed(spec, file).map(|(scene, _)| scene)
}

/// As [`build`], with the scene-file key of each ball of the setup, in its order: `balls[i]`
/// for a listed ball, `layout (ID)` for a ball of the layout.
pub fn build_keyed<X>(spec: SceneFile<X>, file: &str) -> Result<(Scene, Vec<String>), SceneError> {
    let fail = |key: &str, reason: String| SceneError::new(file, key, reason);
    // A file's names were checked as it was read; a built scene's are checked here.
    if let Some((name, _)) = spec
        .params
        .0
        .iter()
        .find(|(n, _)| Params::info(n).is_none())
    {
        return Err(fail(
            &format!("params.{name}"),
            format!("unknown parameter `{name}`"),
        ));
    }
    let params = spec.params.apply_to(Params::default());
    params
        .validate()
        .map_err(|e| fail(&format!("params.{}", e.name), e.reason))?;
    let r = params.ball_radius;
    let (table, dims) = table(&spec, r, file)?;
    let (mut balls, keys) = balls(&spec, &table, &dims, r, file)?;

    let mut strike = None;
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
            offset: c.offset.0,
            elevation: c.elevation,
        };
        // The ball's own motion is checked first: a strike cannot make a bad start good, and
        // the cue is not to blame for it.
        if let Some((field, reason)) = snooker_engine::sim::setup::motion_error(&balls[i], r) {
            return Err(fail(&format!("{}.{field}", keys[i]), reason));
        }
        let before = balls[i].state;
        let s = balls[i]
            .strike(&cue, &params)
            .map_err(|e| fail(&format!("cue.{}", e.key), e.reason))?;
        strike = Some(StruckBall {
            id: c.ball.clone(),
            index: i,
            cue,
            strike: s,
            before,
        });
    }
    let options = options(&spec, file)?;

    let mut setup = Setup {
        table,
        params,
        models: spec.models.apply_to(Default::default()),
        balls,
    };
    setup.validate().map_err(|e| match e.ball {
        Some(i) => {
            let key = if keys[i] == "layout" {
                format!("layout ({})", setup.balls[i].id)
            } else {
                format!("{}.{}", keys[i], e.field)
            };
            fail(&key, e.reason)
        }
        None => fail(&e.field, e.reason),
    })?;
    // Each ball is labelled with the law it starts under (a ball given a velocity or a spin
    // is not at rest), as the engine labels it when the shot begins: the planner and the
    // referee read the label before any simulation.
    for b in &mut setup.balls {
        b.state.motion = snooker_engine::motion::settle(b.state, &setup.params).motion;
    }
    let keys = keys
        .into_iter()
        .zip(&setup.balls)
        .map(|(k, b)| {
            if k == "layout" {
                format!("layout ({})", b.id)
            } else {
                k
            }
        })
        .collect();
    let scene = Scene {
        name: spec.name.unwrap_or_else(|| {
            Path::new(file)
                .file_stem()
                .map_or("scene".into(), |s| s.to_string_lossy().into_owned())
        }),
        setup,
        options,
        strike,
    };
    Ok((scene, keys))
}
