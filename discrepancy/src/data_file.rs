//! Measured data files (formats.md, "Measured data"): a TOML file naming the scene each shot
//! starts from, its tracked centroids (CSV `t,ball,x,y`), its post-event observables (CSV
//! `shot,ball,quantity,when,value,sigma`) and the initial quantities to fit. Errors name the
//! file and the key, or the line and column.
//!
//! Also writes the files `snooker synth` makes.

use crate::data::{MAX_NOISE, MAX_TRACK_COORD, MIN_NOISE, MIN_SIGMA};
use crate::data::{MeasuredStrike, Moment, Quantity};
use crate::data::{Measurement, Model, Nuisance, Observable, ShotData, TrackSample};
use serde::Deserialize;
use snooker_engine::motion::Transition;
use snooker_engine::shown::Shown;
use snooker_engine::{EventKind, Models, Params};
use snooker_scene::{self as scene, Scene, SceneError};
use std::path::{Path, PathBuf};

/// One shot of a data file.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ShotSpec {
    name: Option<String>,
    scene: String,
    tracks: Option<String>,
    observables: Option<String>,
    #[serde(default)]
    fit: Vec<String>,
}

/// A data file: one shot at the top level, or several under `[[shots]]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct DataFile {
    scene: Option<String>,
    tracks: Option<String>,
    observables: Option<String>,
    #[serde(default)]
    fit: Vec<String>,
    noise: Option<f64>,
    #[serde(default)]
    shots: Vec<ShotSpec>,
}

/// Stated noise used when a data file has observables only (it then weighs nothing), m.
const UNUSED_NOISE: f64 = 5e-4;

fn error(file: &Path, key: &str, reason: impl Into<String>) -> SceneError {
    SceneError {
        file: file.display().to_string(),
        key: key.to_string(),
        reason: reason.into(),
    }
}

/// A CSV field: the 1-based column at which it starts, and its trimmed text.
type Field<'a> = (usize, &'a str);
/// A CSV data line: its 1-based number and its fields.
type Row<'a> = (usize, Vec<Field<'a>>);

/// A CSV line's fields with the 1-based column at which each starts.
fn fields(line: &str) -> Vec<Field<'_>> {
    let mut out = Vec::new();
    let mut start = 0;
    for part in line.split(',') {
        let lead = part.len() - part.trim_start().len();
        out.push((line[..start + lead].chars().count() + 1, part.trim()));
        start += part.len() + 1;
    }
    out
}

/// The data lines of a CSV file after its header: (line number, fields). Blank lines and
/// lines starting with `#` are skipped; the header must be `header`.
fn csv_rows<'a>(text: &'a str, file: &Path, header: &[&str]) -> Result<Vec<Row<'a>>, SceneError> {
    let mut rows = Vec::new();
    let mut seen_header = false;
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let f = fields(line);
        if !seen_header {
            let names: Vec<&str> = f.iter().map(|x| x.1).collect();
            if names != header {
                return Err(error(
                    file,
                    "",
                    format!(
                        "line {n}, column 1: the header must be `{}`, found `{trimmed}`",
                        header.join(",")
                    ),
                ));
            }
            seen_header = true;
            continue;
        }
        if f.len() != header.len() {
            return Err(error(
                file,
                "",
                format!(
                    "line {n}, column 1: {} fields where {} are expected ({})",
                    f.len(),
                    header.len(),
                    header.join(",")
                ),
            ));
        }
        rows.push((n, f));
    }
    if !seen_header {
        return Err(error(
            file,
            "",
            format!("no header line `{}`", header.join(",")),
        ));
    }
    Ok(rows)
}

fn number(
    file: &Path,
    line: usize,
    (col, s): (usize, &str),
    what: &str,
) -> Result<f64, SceneError> {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(error(
            file,
            "",
            format!("line {line}, column {col}: {what} must be a finite number, got `{s}`"),
        )),
    }
}

/// A tracked coordinate: a finite number within [`MAX_TRACK_COORD`] of the table's origin.
fn coordinate(file: &Path, line: usize, field: Field<'_>, what: &str) -> Result<f64, SceneError> {
    let v = number(file, line, field, what)?;
    if v.abs() > MAX_TRACK_COORD {
        return Err(error(
            file,
            "",
            format!(
                "line {line}, column {}: {what} must lie within {MAX_TRACK_COORD} m of the \
                 table's origin, got {v:e}",
                field.0
            ),
        ));
    }
    Ok(v)
}

fn ball_index(
    file: &Path,
    line: usize,
    (col, id): Field<'_>,
    ids: &[String],
    scene: &str,
) -> Result<usize, SceneError> {
    ids.iter().position(|b| b == id).ok_or_else(|| {
        error(
            file,
            "",
            format!(
                "line {line}, column {col}: no ball `{id}` in the scene {scene} (it has {})",
                ids.join(", ")
            ),
        )
    })
}

/// Reads a tracks CSV: `t,ball,x,y`, in time order, no later than `max_time` (the scene's
/// `[sim] max_time`, by which its shot has ended).
fn read_tracks(
    path: &Path,
    ids: &[String],
    scene: &str,
    max_time: f64,
) -> Result<Vec<TrackSample>, SceneError> {
    let text = scene::read_text(path)
        .map_err(|e| error(path, "", format!("cannot read the tracks: {e}")))?;
    let mut out: Vec<TrackSample> = Vec::new();
    for (n, f) in csv_rows(&text, path, &["t", "ball", "x", "y"])? {
        let t = number(path, n, f[0], "t (s)")?;
        if t < 0.0 {
            return Err(error(
                path,
                "",
                format!(
                    "line {n}, column {}: t must be >= 0, got {}",
                    f[0].0,
                    Shown(t)
                ),
            ));
        }
        if t > max_time {
            return Err(error(
                path,
                "",
                format!(
                    "line {n}, column {}: t = {t:e} s is after the scene {scene}'s max_time \
                     ({max_time} s), by which its shot has ended",
                    f[0].0
                ),
            ));
        }
        if let Some(last) = out.last()
            && t < last.t
        {
            return Err(error(
                path,
                "",
                format!(
                    "line {n}, column {}: t = {t} comes after t = {}: rows must be in time order",
                    f[0].0, last.t
                ),
            ));
        }
        let ball = ball_index(path, n, f[1], ids, scene)?;
        if out
            .iter()
            .rev()
            .take_while(|s| s.t == t)
            .any(|s| s.ball == ball)
        {
            return Err(error(
                path,
                "",
                format!(
                    "line {n}, column {}: ball `{}` appears twice at t = {t}",
                    f[1].0, f[1].1
                ),
            ));
        }
        let x = coordinate(path, n, f[2], "x (m)")?;
        let y = coordinate(path, n, f[3], "y (m)")?;
        out.push(TrackSample {
            t,
            ball,
            pos: [x, y],
        });
    }
    Ok(out)
}

/// Parses `after:ball_cushion#1` or `rolling:ball_ball#2` (`#1` may be left out).
fn moment(s: &str) -> Result<Moment, String> {
    let (how, rest) = s
        .split_once(':')
        .ok_or_else(|| format!("`{s}` is not `after:KIND#N` or `rolling:KIND#N`"))?;
    let (kind, n) = match rest.split_once('#') {
        Some((k, n)) => (
            k,
            n.parse::<usize>()
                .ok()
                .filter(|&n| n >= 1)
                .ok_or_else(|| format!("`#{n}`: the event count starts at 1"))?,
        ),
        None => (rest, 1),
    };
    // `refresh` renews a law's accelerations and is never listed in a shot's events.
    let kind = EventKind::from_name(kind)
        .filter(|k| *k != EventKind::Transition(Transition::Refresh))
        .ok_or_else(|| format!("`{kind}` is not an event kind"))?;
    match how {
        "after" => Ok(Moment::After { kind, n }),
        "rolling" => Ok(Moment::Rolling { kind, n }),
        _ => Err(format!("`{how}`: the moment is `after` or `rolling`")),
    }
}

/// Reads an observables CSV into per-shot lists (shots by name, or the only shot when the
/// column is empty).
fn read_observables(path: &Path, shots: &[ShotData]) -> Result<Vec<Vec<Observable>>, SceneError> {
    let text = scene::read_text(path)
        .map_err(|e| error(path, "", format!("cannot read the observables: {e}")))?;
    let mut out = vec![Vec::new(); shots.len()];
    // Each (shot, ball, quantity, when) once: a row repeated would weigh twice in the fit
    // (Table I with one row doubled named nothing), as a track's sample repeated is refused.
    let mut seen: Vec<(usize, usize, usize, String, usize)> = Vec::new();
    let header = ["shot", "ball", "quantity", "when", "value", "sigma"];
    for (n, f) in csv_rows(&text, path, &header)? {
        let at = |col: usize, reason: String| {
            error(path, "", format!("line {n}, column {col}: {reason}"))
        };
        let k = if f[0].1.is_empty() && shots.len() == 1 {
            0
        } else {
            shots.iter().position(|s| s.name == f[0].1).ok_or_else(|| {
                at(
                    f[0].0,
                    format!(
                        "no shot `{}` (the shots are {})",
                        f[0].1,
                        shots
                            .iter()
                            .map(|s| s.name.as_str())
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                )
            })?
        };
        let ball = ball_index(path, n, f[1], &shots[k].ids(), &shots[k].name)?;
        let quantity = Quantity::ALL
            .iter()
            .find(|(_, name)| *name == f[2].1)
            .map(|(q, _)| *q)
            .ok_or_else(|| {
                at(
                    f[2].0,
                    format!(
                        "`{}` is not a quantity (one of {})",
                        f[2].1,
                        Quantity::ALL.map(|q| q.1).join(", ")
                    ),
                )
            })?;
        let when = moment(f[3].1).map_err(|r| at(f[3].0, r))?;
        let value = number(path, n, f[4], "value")?;
        let sigma = number(path, n, f[5], "sigma")?;
        let (limit, unit) = (quantity.limit(), quantity.unit());
        if value.abs() > limit {
            return Err(at(
                f[4].0,
                format!(
                    "a {} must lie within {limit} {unit} either way, got {value:e}",
                    f[2].1
                ),
            ));
        }
        if sigma < MIN_SIGMA {
            return Err(at(
                f[5].0,
                format!("sigma must be at least {MIN_SIGMA:e} {unit}, got {sigma:e}"),
            ));
        }
        let q = Quantity::ALL
            .iter()
            .position(|(q, _)| *q == quantity)
            .unwrap_or(0);
        let key = (k, ball, q, f[3].1.to_string());
        if let Some(first) = seen
            .iter()
            .find(|s| (s.0, s.1, s.2, &s.3) == (key.0, key.1, key.2, &key.3))
        {
            return Err(at(
                f[0].0,
                format!(
                    "{} of ball `{}` {} is measured twice (line {} too): each once",
                    f[2].1, f[1].1, f[3].1, first.4
                ),
            ));
        }
        seen.push((key.0, key.1, key.2, key.3, n));
        out[k].push(Observable {
            ball,
            quantity,
            when,
            value,
            sigma,
        });
    }
    Ok(out)
}

/// Parses a `fit` entry: `<ball>.pos|vel|spin` or `strike.speed|aim|offset|elevation`.
fn nuisance(s: &str, ids: &[String], has_strike: bool) -> Result<Nuisance, String> {
    let (who, what) = s.rsplit_once('.').ok_or_else(|| {
        format!("`{s}` is not BALL.pos|vel|spin or strike.speed|aim|offset|elevation")
    })?;
    if who == "strike" && !ids.iter().any(|i| i == "strike") {
        if !has_strike {
            return Err(format!("`{s}`: the scene has no [cue] strike"));
        }
        return match what {
            "speed" => Ok(Nuisance::StrikeSpeed),
            "aim" => Ok(Nuisance::StrikeAim),
            "offset" => Ok(Nuisance::StrikeOffset),
            "elevation" => Ok(Nuisance::StrikeElevation),
            _ => Err(format!(
                "`{what}`: a strike's fitted quantities are speed, aim, offset, elevation"
            )),
        };
    }
    let i = ids
        .iter()
        .position(|b| b == who)
        .ok_or_else(|| format!("no ball `{who}` in the scene (it has {})", ids.join(", ")))?;
    match what {
        "pos" => Ok(Nuisance::Pos(i)),
        "vel" => Ok(Nuisance::Vel(i)),
        "spin" => Ok(Nuisance::Spin(i)),
        _ => Err(format!(
            "`{what}`: a ball's fitted quantities are pos, vel, spin"
        )),
    }
}

/// A shot from a loaded scene: the setup with the strike applied, and the strike to replay.
pub fn shot_from_scene(scene: &Scene) -> ShotData {
    let strike = scene.strike.as_ref().map(|s| MeasuredStrike {
        ball: s.index,
        before: s.before,
        cue: s.cue,
    });
    ShotData {
        name: scene.name.clone(),
        setup: scene.setup.clone(),
        strike,
        samples: Vec::new(),
        observables: Vec::new(),
        nuisances: Vec::new(),
    }
}

fn relative(dir: &Path, p: &str) -> PathBuf {
    dir.join(p)
}

/// The files a data file reads: itself, and each shot's scene, tracks and observables
/// (relative to its directory; only the data file itself if it does not parse). A command's
/// output must be none of them.
pub fn files(path: &Path) -> Vec<PathBuf> {
    let mut out = vec![path.to_path_buf()];
    let Some(spec) = scene::read_text(path)
        .ok()
        .and_then(|text| scene::from_toml::<DataFile>(&text, "").ok())
    else {
        return out;
    };
    let dir = path.parent().unwrap_or(Path::new("."));
    let top = [&spec.scene, &spec.tracks, &spec.observables];
    let named = spec
        .shots
        .iter()
        .flat_map(|s| [Some(&s.scene), s.tracks.as_ref(), s.observables.as_ref()])
        .chain(top.into_iter().map(Option::as_ref))
        .flatten();
    out.extend(named.map(|f| relative(dir, f)));
    out
}

/// Reads a data file and everything it names; `model`, if given, is a model file applied on
/// top of the scenes' own model.
pub fn load(path: &Path, model: Option<&Path>) -> Result<Measurement, SceneError> {
    let text = scene::read_text(path)
        .map_err(|e| error(path, "", format!("cannot read the data file: {e}")))?;
    let file = path.display().to_string();
    let spec: DataFile = scene::from_toml(&text, &file)?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let specs: Vec<(String, ShotSpec)> = match (spec.scene, spec.shots.is_empty()) {
        (Some(scene), true) => vec![(
            String::new(),
            ShotSpec {
                name: None,
                scene,
                tracks: spec.tracks,
                observables: None,
                fit: spec.fit,
            },
        )],
        (None, false) => {
            if spec.tracks.is_some() || !spec.fit.is_empty() {
                return Err(error(
                    path,
                    if spec.tracks.is_some() {
                        "tracks"
                    } else {
                        "fit"
                    },
                    "with [[shots]], tracks and fit belong to each shot",
                ));
            }
            spec.shots
                .into_iter()
                .enumerate()
                .map(|(i, s)| (format!("shots[{i}]."), s))
                .collect()
        }
        (Some(_), false) => {
            return Err(error(
                path,
                "scene",
                "give either scene (one shot) or [[shots]], not both",
            ));
        }
        (None, true) => {
            return Err(error(
                path,
                "scene",
                "missing: name the scene the shot starts from (or list [[shots]])",
            ));
        }
    };
    let mut shots = Vec::new();
    let mut has_tracks = false;
    for (prefix, s) in &specs {
        let scene = scene::load(&relative(dir, &s.scene)).map_err(|mut e| {
            e.reason = format!(
                "{} (the scene named by {file}, key {prefix}scene)",
                e.reason
            );
            e
        })?;
        let mut shot = shot_from_scene(&scene);
        if let Some(n) = &s.name {
            shot.name = n.clone();
        }
        if shots.iter().any(|o: &ShotData| o.name == shot.name) {
            return Err(error(
                path,
                &format!("{prefix}name"),
                format!("two shots are named `{}`", shot.name),
            ));
        }
        let ids = shot.ids();
        for (i, entry) in s.fit.iter().enumerate() {
            let nu = nuisance(entry, &ids, shot.strike.is_some())
                .map_err(|r| error(path, &format!("{prefix}fit[{i}]"), r))?;
            if shot.nuisances.contains(&nu) {
                return Err(error(
                    path,
                    &format!("{prefix}fit[{i}]"),
                    format!("`{entry}` is listed twice"),
                ));
            }
            shot.nuisances.push(nu);
        }
        if let Some(t) = &s.tracks {
            shot.samples =
                read_tracks(&relative(dir, t), &ids, &scene.name, scene.options.max_time)?;
            has_tracks = true;
        }
        if let Some(first) = shots.first() {
            let first: &ShotData = first;
            if first.setup.params != shot.setup.params || first.setup.models != shot.setup.models {
                return Err(error(
                    path,
                    &format!("{prefix}scene"),
                    format!(
                        "the scene's [params] or [models] differ from those of shot `{}`: the \
                         shots of one measurement share one model",
                        first.name
                    ),
                ));
            }
        }
        shots.push(shot);
    }
    // Observables: one file at the top level, or one per shot.
    let top_level = spec.observables.map(|o| relative(dir, &o));
    if let Some(obs) = &top_level {
        for (k, list) in read_observables(obs, &shots)?.into_iter().enumerate() {
            shots[k].observables.extend(list);
        }
    }
    for (k, (_, s)) in specs.iter().enumerate() {
        if let Some(o) = &s.observables {
            let p = relative(dir, o);
            let lists = read_observables(&p, std::slice::from_ref(&shots[k]))?;
            shots[k].observables.extend(lists.into_iter().flatten());
        }
    }
    let noise = match spec.noise {
        Some(v) if (MIN_NOISE..MAX_NOISE).contains(&v) => v,
        Some(v) => {
            return Err(error(
                path,
                "noise",
                format!("must be a number of metres in [{MIN_NOISE:e}, {MAX_NOISE}), got {v:e}"),
            ));
        }
        None if has_tracks => {
            return Err(error(
                path,
                "noise",
                "missing: the tracks' 1-sigma position noise, m",
            ));
        }
        None => UNUSED_NOISE,
    };
    let first = &shots[0].setup;
    let (mut params, mut models): (Params, Models) = (first.params, first.models);
    if let Some(mp) = model {
        let text = scene::read_text(mp)
            .map_err(|e| error(mp, "", format!("cannot read the model file: {e}")))?;
        (params, models) = scene::parse_model(&text, &mp.display().to_string(), params, models)?;
    }
    let m = Measurement {
        shots,
        noise,
        model: Model { params, models },
    };
    m.validate().map_err(|e| error(path, "", e.to_string()))?;
    Ok(m)
}

/// Formats tracks as the CSV of formats.md, with `comment` lines first.
pub fn tracks_csv(samples: &[TrackSample], ids: &[String], comment: &str) -> String {
    let mut out = String::new();
    for line in comment.lines() {
        out += &format!("# {line}\n");
    }
    out += "t,ball,x,y\n";
    for s in samples {
        out += &format!(
            "{:.6},{},{:.6},{:.6}\n",
            s.t, ids[s.ball], s.pos[0], s.pos[1]
        );
    }
    out
}

/// The data file pointing at a shot's scene and tracks.
pub fn data_toml(comment: &str, scene: &str, tracks: &str, noise: f64, fit: &[String]) -> String {
    let mut out = String::new();
    for line in comment.lines() {
        out += &format!("# {line}\n");
    }
    let quoted: Vec<String> = fit.iter().map(|f| format!("{f:?}")).collect();
    out += &format!(
        "scene = {scene:?}\ntracks = {tracks:?}\nnoise = {noise:e}   # m, 1-sigma per coordinate\nfit = [{}]\n",
        quoted.join(", ")
    );
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_moment_names_any_listed_event_kind_and_nothing_else() {
        let after = |kind| Ok(Moment::After { kind, n: 2 });
        assert_eq!(moment("after:lift_off#2"), after(EventKind::LiftOff));
        assert_eq!(
            moment("after:ball_off_table#2"),
            after(EventKind::BallOffTable)
        );
        // A refresh is never listed in a shot: a moment after one would never come.
        for bad in ["after:refresh#1", "after:lift-off", "rolling:nothing#1"] {
            let e = moment(bad).unwrap_err();
            assert!(e.contains("is not an event kind"), "{bad}: {e}");
        }
    }
}
