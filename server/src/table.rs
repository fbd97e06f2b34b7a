//! The table as the page draws it, to scale: the cushion noses and facings, the jaws, the
//! pockets' fall circles and mouths, the spots, the baulk line and the D, and the sizes the
//! page needs (ball radius, the miscue limit for the tip offset); all from the engine's
//! [`Table`] and parameters.

use serde::Serialize;
use snooker_engine::{Params, Table, TableKind};

/// A segment of a cushion's nose or a pocket's facing.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CushionView {
    /// Its name (as in the result's `cushion`).
    pub name: String,
    /// One end (x, y), m.
    pub start: [f64; 2],
    /// The other end, m.
    pub end: [f64; 2],
}

/// A jaw (the rounded end of a nose at a pocket).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JawView {
    /// Centre, m.
    pub centre: [f64; 2],
    /// Radius, m.
    pub radius: f64,
}

/// A pocket.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PocketView {
    /// Its name (`top-left`, `middle-right`, ...).
    pub name: String,
    /// Centre of the fall circle, m.
    pub centre: [f64; 2],
    /// Radius of the fall circle, m.
    pub radius: f64,
    /// Middle of the mouth, m.
    pub mouth: [f64; 2],
}

/// A colour's spot.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SpotView {
    /// The colour.
    pub name: &'static str,
    /// Where, m.
    pub pos: [f64; 2],
}

/// The table and the sizes the page draws with.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TableView {
    /// `snooker` or `open` (no cushions or pockets: the page draws the cloth around the
    /// balls).
    pub kind: TableKind,
    /// Playing area's length, m (0 on the open table).
    pub length: f64,
    /// Playing area's width, m.
    pub width: f64,
    /// Cushion noses and pocket facings.
    pub cushions: Vec<CushionView>,
    /// Jaws.
    pub jaws: Vec<JawView>,
    /// Pockets.
    pub pockets: Vec<PocketView>,
    /// Spots of the colours (snooker table).
    pub spots: Vec<SpotView>,
    /// The baulk line's x, m (snooker table).
    pub baulk_line: Option<f64>,
    /// The D's radius, m, about the brown spot (snooker table).
    pub d_radius: Option<f64>,
    /// Ball radius, m.
    pub ball_radius: f64,
    /// Largest tip offset from the ball's centre before a miscue, m (thesis eq. 7.7).
    pub miscue_radius: f64,
}

fn xy(v: snooker_engine::Vec3) -> [f64; 2] {
    [v.x, v.y]
}

/// The view of `table` with parameters `p`.
pub fn view(table: &Table, p: &Params) -> TableView {
    TableView {
        kind: table.kind,
        length: table.length,
        width: table.width,
        cushions: table
            .cushions
            .iter()
            .map(|c| CushionView {
                name: c.name.clone(),
                start: xy(c.start),
                end: xy(c.end),
            })
            .collect(),
        jaws: table
            .jaws
            .iter()
            .map(|j| JawView {
                centre: xy(j.centre),
                radius: j.radius,
            })
            .collect(),
        pockets: table
            .pockets
            .iter()
            .map(|pk| PocketView {
                name: pk.name.clone(),
                centre: xy(pk.centre),
                radius: pk.radius,
                mouth: xy(pk.mouth),
            })
            .collect(),
        spots: table
            .dims
            .map(|d| {
                d.spots()
                    .iter()
                    .map(|s| SpotView {
                        name: s.name,
                        pos: xy(s.pos),
                    })
                    .collect()
            })
            .unwrap_or_default(),
        baulk_line: table.dims.map(|d| d.baulk_line),
        d_radius: table.dims.map(|d| d.d_radius),
        ball_radius: p.ball_radius,
        miscue_radius: p.miscue_limit * p.ball_radius,
    }
}
