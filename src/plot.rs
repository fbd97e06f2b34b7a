//! Every plot the command line draws (plotters, bitmap PNG): the slips of one impact against
//! the normal impulse (thesis figs. 6.14, 6.15, 6.23) and the discrepancy report's tracks,
//! residuals and observables.

use anyhow::{Context, bail};
use snooker_discrepancy::{Findings, Measurement, locate};
use snooker_engine::impact::impulse::Sample;
use snooker_engine::{Shot, Vec3};
use std::path::Path;

/// The axes in which the slip between the bodies is measured, as in the thesis: for ball-ball
/// X horizontal across the line of centres and Z up (eq. 6.7); for the cushion X along the
/// cushion and Y' up its face (eq. 6.25).
pub type SlipAxes = (Vec3, Vec3);

/// Loads a TrueType font for the plot's text from the system (DejaVu Sans, or any font
/// fontconfig would offer under /usr/share/fonts).
fn register_font() -> anyhow::Result<()> {
    let candidates = [
        "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
        "/usr/share/fonts/TTF/DejaVuSans.ttf",
        "/usr/share/fonts/dejavu/DejaVuSans.ttf",
    ];
    let path = candidates
        .iter()
        .map(Path::new)
        .find(|p| p.exists())
        .context("no TrueType font found for the plot's text (install fonts-dejavu-core)")?;
    let bytes: &'static [u8] = Box::leak(std::fs::read(path)?.into_boxed_slice());
    plotters::style::register_font("sans-serif", plotters::style::FontStyle::Normal, bytes)
        .map_err(|_| anyhow::anyhow!("{} is not a usable font", path.display()))?;
    Ok(())
}

/// Draws slip speed and slip direction against the normal impulse for the contact between the
/// bodies and the cloth contacts (thesis figs. 6.14, 6.15, 6.23).
pub fn slips(samples: &[Sample], axes: SlipAxes, path: &Path) -> anyhow::Result<()> {
    use plotters::prelude::*;
    register_font()?;
    if samples.len() < 2 {
        bail!("too few samples to plot");
    }
    let (x_axis, y_axis) = axes;
    let series = |f: &dyn Fn(&Sample) -> f64| {
        samples
            .iter()
            .map(|s| (s.impulse, f(s)))
            .collect::<Vec<_>>()
    };
    let angle =
        |v: Vec3, x: Vec3, y: Vec3| v.dot(&y).atan2(v.dot(&x)).to_degrees().rem_euclid(360.0);
    let slip = series(&|s| s.slip.norm());
    let phi = series(&|s| angle(s.slip, x_axis, y_axis));
    // A cloth slip is drawn only where the cloth holds that ball (a ball in the air has none).
    let cloth = |i: usize| {
        samples
            .iter()
            .filter(|s| s.pressed[i])
            .map(|s| (s.impulse, s.cloth_slip[i].norm()))
            .collect::<Vec<_>>()
    };
    let cloth_phi = |i: usize| {
        samples
            .iter()
            .filter(|s| s.pressed[i])
            .map(|s| (s.impulse, angle(s.cloth_slip[i], Vec3::x(), Vec3::y())))
            .collect::<Vec<_>>()
    };
    let p_max = samples.last().map_or(1.0, |s| s.impulse);
    let root = BitMapBackend::new(path, (1000, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let (top, bottom) = root.split_vertically(350);
    let s_max = samples
        .iter()
        .flat_map(|s| {
            [
                s.slip.norm(),
                s.cloth_slip[0].norm(),
                s.cloth_slip[1].norm(),
            ]
        })
        .fold(0.0f64, f64::max)
        * 1.1;
    let mut c = ChartBuilder::on(&top)
        .caption("slip speed against normal impulse", ("sans-serif", 20))
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(55)
        .build_cartesian_2d(0.0..p_max, 0.0..s_max.max(1e-9))?;
    c.configure_mesh()
        .x_desc("P_I (N s)")
        .y_desc("slip (m/s)")
        .draw()?;
    let colours = [RED, BLUE, GREEN];
    let labels = [
        "s: contact between the bodies",
        // Body 0 is the incoming ball (the cue ball of a ball-ball impact, the ball of a
        // cushion impact), body 1 the object ball (a cushion has no cloth under it).
        "s': cloth under the incoming ball",
        "s': cloth under the object ball",
    ];
    let data = [slip, cloth(0), cloth(1)];
    for (k, d) in data.iter().enumerate() {
        if d.iter().all(|p| p.1 == 0.0) {
            continue;
        }
        let d = d.clone();
        let col = colours[k];
        c.draw_series(LineSeries::new(d, col.stroke_width(2)))?
            .label(labels[k])
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col));
    }
    c.configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    let mut c = ChartBuilder::on(&bottom)
        .caption("slip direction against normal impulse", ("sans-serif", 20))
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(55)
        .build_cartesian_2d(0.0..p_max, 0.0..360.0)?;
    c.configure_mesh()
        .x_desc("P_I (N s)")
        .y_desc("direction (deg)")
        .draw()?;
    let dirs = [phi, cloth_phi(0), cloth_phi(1)];
    for (k, d) in dirs.iter().enumerate() {
        if data[k].iter().all(|p| p.1 == 0.0) {
            continue;
        }
        // Directions of slips that have stopped carry no meaning: leave them out.
        let shown: Vec<(f64, f64)> = d
            .iter()
            .zip(&data[k])
            .filter(|(_, s)| s.1 > 1e-6 * s_max)
            .map(|(a, _)| *a)
            .collect();
        c.draw_series(
            shown
                .iter()
                .map(|&(x, y)| Circle::new((x, y), 2, colours[k].filled())),
        )?;
    }
    root.present()
        .with_context(|| format!("cannot write {}", path.display()))?;
    Ok(())
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

/// A picture as PNG bytes: `draw` writes it to a file of a private temporary directory, read
/// back and removed, so that an output can be staged with the command's others and put in
/// place with them or not at all ([`crate::output::Outputs`]).
pub fn png_bytes(draw: impl FnOnce(&Path) -> anyhow::Result<()>) -> anyhow::Result<Vec<u8>> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("snooker-plot-{}-{n}", std::process::id()));
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let path = dir.join("plot.png");
    let bytes = draw(&path).and_then(|()| {
        std::fs::read(&path).with_context(|| format!("cannot read {}", path.display()))
    });
    let _ = std::fs::remove_dir_all(&dir);
    bytes
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
    let [r, g, b] = crate::palette::ball(k);
    // Pale balls (the cue ball, the yellow) are drawn darker to show on white paper.
    let luminance = 0.3 * r as f64 + 0.59 * g as f64 + 0.11 * b as f64;
    if luminance > 200.0 {
        plotters::style::RGBColor(r / 2, g / 2, b / 2)
    } else {
        plotters::style::RGBColor(r, g, b)
    }
}

/// Plan view, before and after: measured centroids as dots, simulated paths as lines.
pub fn tracks(m: &Measurement, before: &[Shot], after: &[Shot], path: &Path) -> anyhow::Result<()> {
    use plotters::prelude::*;
    register_font()?;
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
pub fn residuals(
    m: &Measurement,
    before: &[Shot],
    after: &[Shot],
    path: &Path,
) -> anyhow::Result<()> {
    use plotters::prelude::*;
    register_font()?;
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
pub fn observables(o: &Findings, path: &Path) -> anyhow::Result<()> {
    use plotters::prelude::*;
    register_font()?;
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
    let series = |rows: &[locate::ObservableRow],
                  f: &dyn Fn(&locate::ObservableRow) -> Option<f64>|
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
