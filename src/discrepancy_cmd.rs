//! `snooker synth` (measured-like data with effects hidden in it) and `snooker discrepancy`
//! (the workflow on measured data, with its report and plots).

use crate::measured;
use crate::output::write_atomic;
use crate::scene;
use anyhow::{Context, bail};
use snooker_engine::Shot;
use snooker_validation::discrepancy::synth::{Camera, Hidden, Uncatalogued, film};
use snooker_validation::discrepancy::{self as dsc, Effect, Measurement, Model, Outcome};
use std::path::{Path, PathBuf};

/// What `snooker synth` is asked for.
pub struct SynthRequest {
    /// The scene the shot starts from.
    pub scene: PathBuf,
    /// Hidden effects, `NAME=V1[,V2]`.
    pub effects: Vec<String>,
    /// Raw parameter overrides of the truth model, `NAME=VALUE`.
    pub params: Vec<String>,
    /// The camera.
    pub camera: Camera,
    /// Initial quantities the data file asks to fit (default: the strike's speed, or every
    /// moving ball's velocity and spin).
    pub fit: Option<Vec<String>>,
    /// The data file to write (the tracks and a copy of the scene go beside it).
    pub out: PathBuf,
}

/// Parses `--effect NAME=V1[,V2]` into the hidden effects, checking each value against the
/// effect's admissible range under the model they are added to.
pub fn hidden(effects: &[String], base: &Model) -> anyhow::Result<Hidden> {
    let mut h = Hidden::default();
    for spec in effects {
        let (name, values) = spec
            .split_once('=')
            .with_context(|| format!("--effect {spec}: expected NAME=VALUE[,VALUE]"))?;
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
                        "--effect {spec}: {} = {v} is outside [{}, {}] {}",
                        p.name,
                        p.low,
                        p.high,
                        p.unit
                    );
                }
            }
            h.effects.push((e, values));
        } else if let Some(u) = Uncatalogued::from_name(name, values[0]) {
            if values.len() != 1 || !(values[0] >= 0.0 && values[0] < 0.05) {
                bail!("--effect {spec}: {name} takes one amplitude in [0, 0.05) m");
            }
            h.uncatalogued.push(u);
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

/// Writes synthetic measured data; returns a summary.
pub fn synth(req: &SynthRequest) -> anyhow::Result<String> {
    let sc = scene::load(&req.scene).map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut shot = measured::shot_from_scene(&sc);
    let base = Model {
        params: scene::override_params(sc.setup.params, &req.params)?,
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
    let (sim, samples) = film(&shot, &truth, &hidden.uncatalogued, &req.camera)
        .map_err(|e| anyhow::anyhow!("{}: {e}", req.scene.display()))?;
    shot.samples = samples;
    let out = &req.out;
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
    if let Err(e) = crate::output::check_output(out) {
        bail!("-o {}: {e}", out.display());
    }
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
        .chain(hidden.uncatalogued.iter().map(|u| match u {
            Uncatalogued::Wobble { amplitude } => format!("wobble={amplitude}"),
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
        req.camera.fps,
        req.camera.noise * 1e3,
        req.camera.drop_rate * 100.0,
        req.camera.seed
    );
    let scene_name = format!("{stem}.scene.toml");
    let tracks_name = format!("{stem}.csv");
    let scene_text = std::fs::read_to_string(&req.scene)
        .with_context(|| format!("cannot read {}", req.scene.display()))?;
    let files = [
        (dir.join(&scene_name), scene_text),
        (
            dir.join(&tracks_name),
            measured::tracks_csv(&shot.samples, &ids, &comment),
        ),
        (
            out.clone(),
            measured::data_toml(&comment, &scene_name, &tracks_name, req.camera.noise, &fit),
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
        sim.duration,
        out.display(),
        dir.join(&tracks_name).display(),
        dir.join(&scene_name).display()
    ))
}

/// What `snooker discrepancy` is asked for.
pub struct Request {
    /// The data file.
    pub data: PathBuf,
    /// A model file overriding the scenes' model.
    pub model: Option<PathBuf>,
    /// Directory for the full report (JSON, Markdown-free text, plots).
    pub report: Option<PathBuf>,
    /// Where to write the JSON report.
    pub json: Option<PathBuf>,
}

/// Loads the data (bad input: the error is the user's).
pub fn load(req: &Request) -> anyhow::Result<Measurement> {
    measured::load(&req.data, req.model.as_deref()).map_err(|e| anyhow::anyhow!("{e}"))
}

/// Runs the workflow.
pub fn run(m: &Measurement) -> anyhow::Result<Outcome> {
    dsc::run(m, &dsc::Options::default()).map_err(|e| anyhow::anyhow!("{e}"))
}

/// Writes the JSON report and the report directory.
pub fn write(req: &Request, m: &Measurement, o: &Outcome) -> anyhow::Result<Vec<PathBuf>> {
    let doc = dsc::report::json(m, o);
    let text = serde_json::to_string_pretty(&doc)? + "\n";
    let mut written = Vec::new();
    if let Some(p) = &req.json {
        write_atomic(p, text.as_bytes())?;
        written.push(p.clone());
    }
    if let Some(dir) = &req.report {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
        let json_path = dir.join("report.json");
        write_atomic(&json_path, text.as_bytes())?;
        written.push(json_path);
        let txt = dir.join("summary.txt");
        write_atomic(&txt, dsc::report::text(m, o).as_bytes())?;
        written.push(txt);
        if m.shots.iter().any(|s| !s.samples.is_empty()) {
            let p = dir.join("tracks.png");
            plot_tracks(m, &o.baseline.sims, &o.last.sims, &p)?;
            written.push(p);
            let p = dir.join("residuals.png");
            plot_residuals(m, &o.baseline.sims, &o.last.sims, &p)?;
            written.push(p);
        }
        if m.shots.iter().any(|s| !s.observables.is_empty()) {
            let p = dir.join("observables.png");
            plot_observables(o, &p)?;
            written.push(p);
        }
        written.extend(write_overlays(m, o, dir)?);
    }
    Ok(written)
}

/// Colour of the measured centroids in the overlay recordings.
pub const MEASURED_COLOR: [u8; 3] = [255, 0, 255];
/// Colour of the start model's ball centres in the overlay recordings.
pub const START_MODEL_COLOR: [u8; 3] = [255, 150, 0];

/// The overlay recording's file name for shot `index` of `m`: `overlay.rrd` for a single
/// shot, else `overlay-<index>-<name>.rrd` with the name reduced to safe characters.
pub fn overlay_file(m: &Measurement, index: usize) -> String {
    if m.shots.len() == 1 {
        return "overlay.rrd".into();
    }
    let name: String = m.shots[index]
        .name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' {
                c
            } else {
                '_'
            }
        })
        .take(40)
        .collect();
    format!("overlay-{index}-{name}.rrd")
}

/// One Rerun recording per tracked shot: the final model's shot as balls, with the measured
/// centroids (`measured/<ball>`) and the start model's centres at the same times
/// (`start_model/<ball>`) as points on the cloth.
fn write_overlays(m: &Measurement, o: &Outcome, dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let mut written = Vec::new();
    for (i, shot) in m.shots.iter().enumerate() {
        if shot.samples.is_empty() {
            continue;
        }
        let (start, last) = (&o.baseline.sims[i], &o.last.sims[i]);
        let r = m.model.params.ball_radius;
        let mut overlays = Vec::new();
        for (b, id) in shot.ids().into_iter().enumerate() {
            let seen: Vec<_> = shot.samples.iter().filter(|s| s.ball == b).collect();
            if seen.is_empty() {
                continue;
            }
            let at_z = |x: f64, y: f64| snooker_engine::Vec3::new(x, y, r);
            overlays.push(crate::record::Overlay {
                entity: vec!["measured".into(), id.clone()],
                points: seen
                    .iter()
                    .map(|s| (s.t, at_z(s.pos[0], s.pos[1])))
                    .collect(),
                color: MEASURED_COLOR,
                radius: 0.008,
            });
            overlays.push(crate::record::Overlay {
                entity: vec!["start_model".into(), id],
                points: seen
                    .iter()
                    .map(|s| (s.t, start.tracks[b].state_at(s.t, &start.params).pos))
                    .collect(),
                color: START_MODEL_COLOR,
                radius: 0.006,
            });
        }
        let view = scene::Scene {
            name: format!("{} (final model)", shot.name),
            setup: shot.setup.clone(),
            options: snooker_engine::SimOptions::default(),
            strike: None,
            before_strike: None,
        };
        let bytes = crate::record::encode_with_overlays(
            &view,
            last,
            &crate::record::RecordOptions::default(),
            &overlays,
        )
        .with_context(|| format!("overlay recording of shot {}", shot.name))?;
        let p = dir.join(overlay_file(m, i));
        write_atomic(&p, &bytes)?;
        written.push(p);
    }
    Ok(written)
}

const TITLE: (&str, u32) = ("sans-serif", 20);

/// A chart of this module: f64 axes on a bitmap.
type Chart<'a, 'b> = plotters::chart::ChartContext<
    'a,
    plotters::backend::BitMapBackend<'b>,
    plotters::coord::cartesian::Cartesian2d<
        plotters::coord::types::RangedCoordf64,
        plotters::coord::types::RangedCoordf64,
    >,
>;

/// Draws the legend of the labelled series.
fn legend<'a, 'b: 'a>(c: &mut Chart<'a, 'b>) -> anyhow::Result<()> {
    use plotters::style::{BLACK, Color, WHITE};
    c.configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    Ok(())
}

/// Writes the picture to `path`.
fn present(
    root: &plotters::drawing::DrawingArea<
        plotters::backend::BitMapBackend<'_>,
        plotters::coord::Shift,
    >,
    path: &Path,
) -> anyhow::Result<()> {
    root.present()
        .with_context(|| format!("cannot write {}", path.display()))
}

fn rgb(k: snooker_engine::BallKind) -> plotters::style::RGBColor {
    let [r, g, b] = k.rgb();
    // Pale balls (the cue ball, the yellow) are drawn darker to show on white paper.
    let luminance = 0.3 * r as f64 + 0.59 * g as f64 + 0.11 * b as f64;
    if luminance > 200.0 {
        plotters::style::RGBColor(r / 2, g / 2, b / 2)
    } else {
        plotters::style::RGBColor(r, g, b)
    }
}

/// Plan view, before and after: measured centroids as dots, simulated paths as lines.
fn plot_tracks(
    m: &Measurement,
    before: &[Shot],
    after: &[Shot],
    path: &Path,
) -> anyhow::Result<()> {
    use plotters::prelude::*;
    crate::impact_cmd::register_font()?;
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for s in m.shots.iter().flat_map(|s| &s.samples) {
        x0 = x0.min(s.pos[0]);
        x1 = x1.max(s.pos[0]);
        y0 = y0.min(s.pos[1]);
        y1 = y1.max(s.pos[1]);
    }
    let pad = 0.05;
    let root = BitMapBackend::new(path, (1400, 650)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((1, 2));
    for (panel, (sims, label)) in panels
        .iter()
        .zip([(before, "start model"), (after, "after the named effects")])
    {
        let mut c = ChartBuilder::on(panel)
            .caption(
                format!("measured (dots) and simulated (lines): {label}"),
                TITLE,
            )
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(50)
            .build_cartesian_2d((x0 - pad)..(x1 + pad), (y0 - pad)..(y1 + pad))?;
        c.configure_mesh().x_desc("x (m)").y_desc("y (m)").draw()?;
        for (shot, sim) in m.shots.iter().zip(sims) {
            let end = shot.last_sample();
            for (b, track) in sim.tracks.iter().enumerate() {
                if !shot.samples.iter().any(|s| s.ball == b) {
                    continue;
                }
                let col = rgb(track.kind);
                let n = (end / 0.005).ceil() as usize;
                let line: Vec<(f64, f64)> = (0..=n)
                    .map(|k| {
                        let st = track.state_at(k as f64 * 0.005, &sim.params);
                        (st.pos.x, st.pos.y)
                    })
                    .collect();
                c.draw_series(LineSeries::new(line, col.stroke_width(1)))?;
                c.draw_series(
                    shot.samples
                        .iter()
                        .filter(|s| s.ball == b)
                        .map(|s| Circle::new((s.pos[0], s.pos[1]), 2, col.filled())),
                )?;
            }
        }
    }
    present(&root, path)
}

/// Distance between measured and simulated centre against time, before and after.
fn plot_residuals(
    m: &Measurement,
    before: &[Shot],
    after: &[Shot],
    path: &Path,
) -> anyhow::Result<()> {
    use plotters::prelude::*;
    crate::impact_cmd::register_font()?;
    let residuals = |sims: &[Shot]| -> Vec<(f64, f64, snooker_engine::BallKind)> {
        let mut out = Vec::new();
        for (shot, sim) in m.shots.iter().zip(sims) {
            for s in &shot.samples {
                let st = sim.tracks[s.ball].state_at(s.t, &sim.params);
                let d = (st.pos.x - s.pos[0]).hypot(st.pos.y - s.pos[1]);
                out.push((s.t, d * 1e3, sim.tracks[s.ball].kind));
            }
        }
        out
    };
    let t_max = m
        .shots
        .iter()
        .map(|s| s.last_sample())
        .fold(0.0, f64::max)
        .max(1e-3);
    let root = BitMapBackend::new(path, (1200, 800)).into_drawing_area();
    root.fill(&WHITE)?;
    let (top, bottom) = root.split_vertically(400);
    for (area, (sims, label)) in [
        (&top, (before, "start model")),
        (&bottom, (after, "after the named effects")),
    ] {
        let r = residuals(sims);
        let d_max = r.iter().map(|x| x.1).fold(3.0 * m.noise * 1e3, f64::max) * 1.05;
        let mut c = ChartBuilder::on(area)
            .caption(
                format!("|simulated - measured| against time: {label}"),
                TITLE,
            )
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(55)
            .build_cartesian_2d(0.0..t_max, 0.0..d_max)?;
        c.configure_mesh()
            .x_desc("t (s)")
            .y_desc("distance (mm)")
            .draw()?;
        c.draw_series(
            r.iter()
                .map(|&(t, d, k)| Circle::new((t, d), 2, rgb(k).filled())),
        )?;
        // Noise alone: the distance of two independent 1-sigma coordinates has RMS sqrt(2) sigma.
        let level = std::f64::consts::SQRT_2 * m.noise * 1e3;
        c.draw_series(LineSeries::new(
            vec![(0.0, level), (t_max, level)],
            BLACK.stroke_width(1),
        ))?
        .label("RMS of noise alone")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK));
        legend(&mut c)?;
    }
    present(&root, path)
}

/// Observables: measured, start model and final model against the speed of the event they
/// follow (thesis fig. 5.7 for cushion rebounds).
fn plot_observables(o: &Outcome, path: &Path) -> anyhow::Result<()> {
    use plotters::prelude::*;
    crate::impact_cmd::register_font()?;
    let before = &o.baseline_state.location.observables;
    let after = &o.final_state.location.observables;
    let x = |i: usize| before[i].event_speed.unwrap_or(i as f64);
    let n = before.len();
    if n == 0 {
        bail!("no observables to plot");
    }
    let xs: Vec<f64> = (0..n).map(x).collect();
    let ys: Vec<f64> = before
        .iter()
        .chain(after)
        .flat_map(|r| [r.measured, r.simulated.unwrap_or(r.measured)])
        .collect();
    let (lo, hi) = ys
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let (xl, xh) = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let span = (hi - lo).max(1e-6);
    let root = BitMapBackend::new(path, (1100, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let units: Vec<&str> = before.iter().map(|r| r.quantity).collect();
    let mut c = ChartBuilder::on(&root)
        .caption(
            format!("observables ({}) against the event's normal speed", {
                let mut u = units.clone();
                u.dedup();
                u.join(", ")
            }),
            TITLE,
        )
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(55)
        .build_cartesian_2d(
            (xl - 0.05 * (xh - xl).max(0.1))..(xh + 0.05 * (xh - xl).max(0.1)),
            (lo - 0.05 * span)..(hi + 0.05 * span),
        )?;
    c.configure_mesh()
        .x_desc(if before[0].event_speed.is_some() {
            "normal speed of the event (m/s)"
        } else {
            "observable"
        })
        .y_desc("value")
        .draw()?;
    let series = |rows: &[dsc::locate::ObservableRow],
                  f: &dyn Fn(&dsc::locate::ObservableRow) -> Option<f64>|
     -> Vec<(f64, f64)> {
        rows.iter()
            .enumerate()
            .filter_map(|(i, r)| f(r).map(|v| (xs[i], v)))
            .collect()
    };
    let measured = series(before, &|r| Some(r.measured));
    let start = series(before, &|r| r.simulated);
    let end = series(after, &|r| r.simulated);
    c.draw_series(measured.iter().map(|&p| Circle::new(p, 4, BLACK.filled())))?
        .label("measured")
        .legend(|(x, y)| Circle::new((x + 10, y), 4, BLACK.filled()));
    c.draw_series(start.iter().map(|&p| Cross::new(p, 5, RED.stroke_width(2))))?
        .label("start model")
        .legend(|(x, y)| Cross::new((x + 10, y), 5, RED.stroke_width(2)));
    c.draw_series(
        end.iter()
            .map(|&p| TriangleMarker::new(p, 5, BLUE.filled())),
    )?
    .label("after the named effects")
    .legend(|(x, y)| TriangleMarker::new((x + 10, y), 5, BLUE.filled()));
    legend(&mut c)?;
    present(&root, path)
}
