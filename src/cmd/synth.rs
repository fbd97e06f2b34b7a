//! `snooker synth`: measured-like data with effects hidden in it: the scene simulated under its
//! model plus the hidden effects, filmed with camera noise and dropped frames, written as a
//! measured-data file (formats.md) with its tracks and scene beside it.

use super::bad_input;
use crate::output::{check_output, write_atomic};
use anyhow::{Context, bail};
use snooker_discrepancy::data_file;
use snooker_discrepancy::synth::{Camera, Hidden, Uncatalogued, film};
use snooker_discrepancy::{DiscrepancyError, Effect, Model};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Arguments of `snooker synth`.
#[derive(clap::Args)]
pub struct Args {
    /// The scene the shot starts from (its model is the one without the hidden effects).
    scene: PathBuf,
    /// Hide an effect: a catalogue id with its value(s), e.g. table_slope=0.001,-0.0005,
    /// or a law outside the catalogue's forms: wobble=AMPLITUDE_M, anisotropic_rolling=MU_Y,
    /// throw_falling_with_speed=MU_SLOW, rolling_rising_with_speed=SPEED,
    /// cushion_angle_restitution=DROP. Repeatable.
    #[arg(long = "effect", value_name = "NAME=VALUE[,VALUE]")]
    effects: Vec<String>,
    /// Override a parameter of the truth model, NAME=VALUE (repeatable).
    #[arg(long = "param", value_name = "NAME=VALUE")]
    params: Vec<String>,
    /// Camera frames per second.
    #[arg(long, default_value_t = 100.0, allow_negative_numbers = true)]
    fps: f64,
    /// Camera position noise, 1-sigma per coordinate, millimetres.
    #[arg(
        long,
        value_name = "MM",
        default_value_t = 0.5,
        allow_negative_numbers = true
    )]
    noise: f64,
    /// Seed of the noise and the dropped frames.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Share of frames lost.
    #[arg(long, default_value_t = 0.02, allow_negative_numbers = true)]
    drop: f64,
    /// Longest recording, s.
    #[arg(long, default_value_t = 20.0, allow_negative_numbers = true)]
    duration: f64,
    /// Initial quantities the data file asks to fit, comma-separated (default: the
    /// strike's speed, or every moving ball's vel and spin).
    #[arg(long, value_delimiter = ',', value_name = "LIST")]
    fit: Option<Vec<String>>,
    /// The data file to write (DATA.toml; the tracks DATA.csv and the scene
    /// DATA.scene.toml go beside it).
    #[arg(short = 'o', long = "out", value_name = "DATA.toml")]
    out: PathBuf,
}

/// Runs the command.
pub fn run(args: Args) -> ExitCode {
    // The data file states the noise, and `snooker discrepancy` weights the tracks by it:
    // below its floor the file written could not be read back.
    let floor = snooker_discrepancy::data::MIN_NOISE;
    if args.noise.is_finite() && args.noise >= 0.0 && args.noise * 1e-3 < floor {
        return bad_input(format!(
            "--noise {}: below {} mm the data file could not be read by `snooker discrepancy` \
             (it weights the tracks by the noise); use {} for tracks as good as exact",
            args.noise,
            floor * 1e3,
            floor * 1e3
        ));
    }
    let camera = Camera {
        fps: args.fps,
        noise: args.noise * 1e-3,
        drop_rate: args.drop,
        seed: args.seed,
        max_duration: args.duration,
    };
    // The camera's settings are flags: named as given (the noise in mm), not blamed on the
    // scene file as the film's own check would.
    if let Err(DiscrepancyError::Camera { setting, range, .. }) =
        snooker_discrepancy::synth::check_camera(&camera)
    {
        let (flag, given, range) = match setting {
            "fps" => ("--fps", args.fps, range.to_string()),
            "noise" => ("--noise", args.noise, "in [0, 100) mm".to_string()),
            "drop rate" => ("--drop", args.drop, range.to_string()),
            _ => ("--duration", args.duration, "positive (s)".to_string()),
        };
        return bad_input(format!("{flag} {given}: must be {range}"));
    }
    match synth(&args, &camera) {
        Ok(text) => {
            out!("{text}");
            ExitCode::SUCCESS
        }
        Err(e) => bad_input(format!("{e:#}")),
    }
}

/// Parses `--effect NAME=V1[,V2]` into the hidden effects, checking each value against the
/// effect's admissible range under the model they are added to.
fn hidden(effects: &[String], base: &Model) -> anyhow::Result<Hidden> {
    let mut h = Hidden::default();
    let mut named: Vec<&str> = Vec::new();
    for spec in effects {
        let (name, values) = spec
            .split_once('=')
            .with_context(|| format!("--effect {spec}: expected NAME=VALUE[,VALUE]"))?;
        // The data file lists every --effect as the hidden truth: a second value for one
        // effect would be listed but not used.
        if named.contains(&name.trim()) {
            bail!(
                "--effect {spec}: {} is hidden twice; give it once",
                name.trim()
            );
        }
        named.push(name.trim());
        let values: Vec<f64> = values
            .split(',')
            .map(|v| {
                v.trim()
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .with_context(|| format!("--effect {spec}: `{v}` is not a finite number"))
            })
            .collect::<anyhow::Result<_>>()?;
        let name = name.trim();
        if let Some(e) = Effect::from_id(name) {
            let model = h.truth(base);
            let params = e.params(&model);
            if params.is_empty() {
                bail!(
                    "--effect {spec}: {name} cannot be switched on in this model (a tilt needs \
                     rolling resistance to hold resting balls)"
                );
            }
            if params.len() != values.len() {
                bail!(
                    "--effect {spec}: {name} takes {} value(s): {}",
                    params.len(),
                    params.iter().map(|p| p.name).collect::<Vec<_>>().join(", ")
                );
            }
            for (p, v) in params.iter().zip(&values) {
                if *v < p.low || *v > p.high {
                    bail!(
                        "--effect {spec}: {} = {v} is outside [{}, {}]{}",
                        p.name,
                        p.low,
                        p.high,
                        p.unit_suffix()
                    );
                }
            }
            h.effects.push((e, values));
        } else if let Some(u) = Uncatalogued::from_name(name, &values) {
            match u {
                Ok(u) => h.uncatalogued.push(u),
                Err(why) => bail!("--effect {spec}: {why}"),
            }
        } else {
            bail!(
                "--effect {spec}: unknown effect `{name}` (catalogue: {}; outside it: {})",
                Effect::ALL.map(|e| e.id()).join(", "),
                Uncatalogued::NAMES.join(", ")
            );
        }
    }
    Ok(h)
}

/// The files `-o DATA.toml` stands for: the data file, and beside it its tracks (DATA.csv) and
/// scene (DATA.scene.toml).
struct Outputs {
    /// The directory they go in.
    dir: PathBuf,
    /// The scene's file name.
    scene_name: String,
    /// The tracks' file name.
    tracks_name: String,
}

impl Outputs {
    /// The files of `-o out`, each checked before any work (so that none is written when one
    /// cannot be), and `out` not the scene the shot is read from.
    fn of(out: &Path, scene: &Path) -> anyhow::Result<Outputs> {
        if out.extension().and_then(|e| e.to_str()) != Some("toml") {
            bail!(
                "-o {}: the data file's name must end in .toml",
                out.display()
            );
        }
        let stem = out
            .file_stem()
            .and_then(|s| s.to_str())
            .context("-o: no file name")?;
        let dir = out
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        let files = Outputs {
            dir: dir.to_path_buf(),
            scene_name: format!("{stem}.scene.toml"),
            tracks_name: format!("{stem}.csv"),
        };
        for path in [
            out.to_path_buf(),
            dir.join(&files.tracks_name),
            dir.join(&files.scene_name),
        ] {
            if let Err(e) = check_output(&path) {
                bail!("-o {}: {}: {e}", out.display(), path.display());
            }
        }
        if crate::output::same_file(out, scene) {
            bail!(
                "-o {}: is the scene the shot is read from (the data file would replace it)",
                out.display()
            );
        }
        Ok(files)
    }
}

/// Writes synthetic measured data; returns a summary.
fn synth(req: &Args, camera: &Camera) -> anyhow::Result<String> {
    let out = &req.out;
    let names = Outputs::of(out, &req.scene)?;
    let sc = snooker_scene::load(&req.scene)?;
    let mut shot = data_file::shot_from_scene(&sc);
    let base = Model {
        params: super::spec::params(sc.setup.params, &req.params).map_err(anyhow::Error::msg)?,
        models: sc.setup.models,
    };
    let hidden = hidden(&req.effects, &base)?;
    let truth = hidden.truth(&base);
    let ids = shot.ids();
    let fit: Vec<String> = match &req.fit {
        Some(f) => f.clone(),
        None if shot.strike.is_some() => vec!["strike.speed".into()],
        None => shot
            .setup
            .balls
            .iter()
            .filter(|b| b.state.motion.is_moving() || b.state.spin.norm() > 0.0)
            .flat_map(|b| [format!("{}.vel", b.id), format!("{}.spin", b.id)])
            .collect(),
    };
    // The data file must read back: check the fit list the way the reader will.
    for f in &fit {
        let Some((who, what)) = f.rsplit_once('.') else {
            bail!("--fit {f}: expected BALL.pos|vel|spin or strike.speed|aim|offset|elevation");
        };
        let ok = if who == "strike" {
            shot.strike.is_some() && ["speed", "aim", "offset", "elevation"].contains(&what)
        } else {
            ids.iter().any(|i| i == who) && ["pos", "vel", "spin"].contains(&what)
        };
        if !ok {
            bail!(
                "--fit {f}: not a quantity of this scene (balls {})",
                ids.join(", ")
            );
        }
    }
    let (duration, samples) = film(&shot, &truth, &hidden.uncatalogued, camera)
        .map_err(|e| anyhow::anyhow!("{}: {e}", req.scene.display()))?;
    shot.samples = samples;
    let truth_text: Vec<String> = hidden
        .effects
        .iter()
        .map(|(e, v)| {
            format!(
                "{}={}",
                e.id(),
                v.iter()
                    .map(|x| x.to_string())
                    .collect::<Vec<_>>()
                    .join(",")
            )
        })
        .chain(hidden.uncatalogued.iter().map(|u| {
            let (name, value) = u.name_value();
            format!("{name}={value}")
        }))
        .chain(req.params.iter().cloned())
        .collect();
    let comment = format!(
        "Synthetic measurement by `snooker synth` from {}\nhidden: {}\ncamera: {} frames/s, \
         noise {} mm, {}% frames dropped, seed {}",
        req.scene.display(),
        if truth_text.is_empty() {
            "nothing".into()
        } else {
            truth_text.join(" ")
        },
        camera.fps,
        camera.noise * 1e3,
        camera.drop_rate * 100.0,
        camera.seed
    );
    let (dir, scene_name, tracks_name) = (&names.dir, &names.scene_name, &names.tracks_name);
    let scene_text = snooker_scene::read_text(&req.scene)
        .with_context(|| format!("cannot read {}", req.scene.display()))?;
    let files = [
        (dir.join(scene_name), scene_text),
        (
            dir.join(tracks_name),
            data_file::tracks_csv(&shot.samples, &ids, &comment),
        ),
        (
            out.clone(),
            data_file::data_toml(&comment, scene_name, tracks_name, camera.noise, &fit),
        ),
    ];
    for (path, text) in &files {
        write_atomic(path, text.as_bytes())?;
    }
    Ok(format!(
        "{}\n{} samples of {} balls over {:.2} s (the shot lasts {:.2} s)\nwrote {}, {}, {}\n",
        comment,
        shot.samples.len(),
        ids.len(),
        shot.last_sample(),
        duration,
        out.display(),
        dir.join(tracks_name).display(),
        dir.join(scene_name).display()
    ))
}
