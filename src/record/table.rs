//! The static table: cloth, cushions, pockets and markings, in the table frame (m, z up).
//! The engine's own geometry (nose lines, facings, jaw arcs, fall circles) is drawn exactly;
//! the cushion rubber and the wooden rail behind the noses are for looks only.

use super::{RecordError, f32x3, rerun_err};
use rerun::{Boxes3D, Color, Cylinders3D, FillMode, LineStrips3D, Points3D, RecordingStream};
use snooker_engine::{BallState, Params, Table, TableKind, Vec3};

/// Cloth colour.
const CLOTH: [u8; 3] = [28, 110, 52];
/// Width of the cushion rubber behind a nose, m (looks only).
const RUBBER: f64 = 0.05;
/// Width of the wooden rail behind the rubber, m (looks only).
const RAIL: f64 = 0.09;
/// Margin of cloth around the balls' extent on the open table, m.
const OPEN_MARGIN: f64 = 0.3;
/// Markings sit this far above the cloth so that they are not hidden in it, m.
const LIFT: f64 = 0.0005;

fn put(
    rec: &RecordingStream,
    entity: &str,
    arch: &impl rerun::AsComponents,
) -> Result<(), RecordError> {
    rec.log_static(entity, arch).map_err(rerun_err)
}

/// A box over the plan rectangle `a`..`b`, from height `z0` up by `height`: (centre, half size).
fn slab(a: Vec3, b: Vec3, z0: f64, height: f64) -> ([f32; 3], [f32; 3]) {
    let c = 0.5 * (a + b);
    let h = 0.5 * (b - a);
    (
        [c.x as f32, c.y as f32, (z0 + 0.5 * height) as f32],
        [h.x.abs() as f32, h.y.abs() as f32, (0.5 * height) as f32],
    )
}

/// The plan rectangle a view should frame: the table with its rails, or on the open table the
/// balls' extent with a margin. `None` when there is nothing to show.
pub fn extent(table: &Table, states: &[Vec<BallState>]) -> Option<(Vec3, Vec3)> {
    if table.kind == TableKind::Open {
        let (mut lo, mut hi) = (Vec3::repeat(f64::INFINITY), Vec3::repeat(f64::NEG_INFINITY));
        for s in states.iter().flatten().filter(|s| s.motion.in_play()) {
            lo = lo.inf(&s.pos);
            hi = hi.sup(&s.pos);
        }
        let m = Vec3::new(OPEN_MARGIN, OPEN_MARGIN, 0.0);
        (lo.x <= hi.x).then(|| (lo.xy().push(0.0) - m, hi.xy().push(0.0) + m))
    } else {
        let edge = RUBBER + RAIL;
        Some((
            Vec3::new(-edge, -edge, 0.0),
            Vec3::new(table.length + edge, table.width + edge, 0.0),
        ))
    }
}

/// Solid boxes of one colour, from (centre, half size) pairs.
fn boxes(slabs: Vec<([f32; 3], [f32; 3])>, colour: [u8; 3]) -> Boxes3D {
    let (centres, halves): (Vec<_>, Vec<_>) = slabs.into_iter().unzip();
    Boxes3D::from_centers_and_half_sizes(centres, halves)
        .with_colors([Color::from_rgb(colour[0], colour[1], colour[2])])
        .with_fill_mode(FillMode::Solid)
}

/// Logs the table (or, on the open table, a cloth patch over `extent`).
pub fn log(
    rec: &RecordingStream,
    table: &Table,
    params: &Params,
    extent: Option<(Vec3, Vec3)>,
) -> Result<(), RecordError> {
    let Some((lo, hi)) = extent else {
        return Ok(());
    };
    put(
        rec,
        "table/cloth",
        &boxes(vec![slab(lo, hi, -0.02, 0.02)], CLOTH),
    )?;
    if table.kind == TableKind::Open {
        return Ok(());
    }
    let (l, w) = (table.length, table.width);
    let nose_h = params.cushion_height;
    let top = nose_h + 0.006;

    // Rubber behind each straight nose (facings excepted: the pockets are there), then the
    // rail around it all (plan corners of its four sides).
    let rubber = table
        .cushions
        .iter()
        .filter(|c| !c.name.contains("facing"))
        .map(|c| slab(c.start, c.end - c.normal * RUBBER, 0.0, top))
        .collect();
    put(rec, "table/cushions", &boxes(rubber, [22, 88, 42]))?;
    let (r, e) = (RUBBER, RUBBER + RAIL);
    let rails = [
        ([-e, -e], [l + e, -r]),
        ([-e, w + r], [l + e, w + e]),
        ([-e, -r], [-r, w + r]),
        ([l + r, -r], [l + e, w + r]),
    ]
    .iter()
    .map(|&([x0, y0], [x1, y1])| slab(Vec3::new(x0, y0, 0.0), Vec3::new(x1, y1, 0.0), 0.0, top))
    .collect();
    put(rec, "table/rails", &boxes(rails, [92, 52, 24]))?;

    // The engine's contact geometry at the nose height: noses, facings and jaw arcs.
    let at_nose = |p: Vec3| [p.x as f32, p.y as f32, nose_h as f32];
    let mut lines: Vec<Vec<[f32; 3]>> = table
        .cushions
        .iter()
        .map(|c| vec![at_nose(c.start), at_nose(c.end)])
        .collect();
    lines.extend(
        table
            .jaws
            .iter()
            .map(|j| circle(j.centre, j.radius, nose_h, 0.0, std::f64::consts::TAU)),
    );
    put(
        rec,
        "table/noses",
        &LineStrips3D::new(lines)
            .with_colors([Color::from_rgb(235, 235, 210)])
            .with_radii([rerun::Radius::new_scene_units(0.0015)]),
    )?;

    // Pockets: a black well over the fall circle (a ball is captured once its centre is inside).
    let wells = table
        .pockets
        .iter()
        .map(|p| f32x3(p.centre + Vec3::z() * 0.5 * top));
    put(
        rec,
        "table/pockets",
        &Cylinders3D::from_lengths_and_radii(
            vec![(top + 0.002) as f32; table.pockets.len()],
            table.pockets.iter().map(|p| p.radius as f32),
        )
        .with_centers(wells)
        .with_colors([Color::from_rgb(8, 8, 8)])
        .with_fill_mode(FillMode::Solid),
    )?;

    if let Some(d) = &table.dims {
        let white = Color::from_rgb(235, 235, 235);
        let y_mid = 0.5 * w;
        let baulk = vec![
            [d.baulk_line as f32, 0.0, LIFT as f32],
            [d.baulk_line as f32, w as f32, LIFT as f32],
        ];
        // The D: the semicircle on the baulk side of the line.
        let dee = circle(
            Vec3::new(d.baulk_line, y_mid, 0.0),
            d.d_radius,
            LIFT,
            0.5 * std::f64::consts::PI,
            1.5 * std::f64::consts::PI,
        );
        put(
            rec,
            "table/markings",
            &LineStrips3D::new([baulk, dee])
                .with_colors([white])
                .with_radii([rerun::Radius::new_scene_units(0.002)]),
        )?;
        put(
            rec,
            "table/spots",
            &Points3D::new(d.spots().iter().map(|s| {
                let p = s.pos;
                [p.x as f32, p.y as f32, LIFT as f32]
            }))
            .with_labels(d.spots().iter().map(|s| s.name))
            .with_show_labels(false)
            .with_colors([white])
            .with_radii([rerun::Radius::new_scene_units(0.004)]),
        )?;
    }
    Ok(())
}

/// An arc of radius `r` about `centre` (plan) at height `z`, from angle `a0` to `a1`.
fn circle(centre: Vec3, r: f64, z: f64, a0: f64, a1: f64) -> Vec<[f32; 3]> {
    let n = 64;
    (0..=n)
        .map(|k| {
            let a = a0 + (a1 - a0) * k as f64 / n as f64;
            [
                (centre.x + r * a.cos()) as f32,
                (centre.y + r * a.sin()) as f32,
                z as f32,
            ]
        })
        .collect()
}
