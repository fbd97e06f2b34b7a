//! The table: cushion noses (straight segments), pocket jaws (arcs), pocket facings and
//! pocket falls, all in plan view at the height of the cushion nose.
//!
//! Plan vectors are [`Vec3`] with z = 0 so that they combine directly with ball paths.

pub mod layout;
pub mod snooker;

use crate::ball::Vec3;
use crate::shown::Shown;
use serde::{Deserialize, Serialize};

pub use snooker::SnookerDims;

/// Which table a scene is played on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum TableKind {
    /// A full-size snooker table (WPBSA playing area, six pockets).
    #[default]
    Snooker,
    /// Endless cloth: no cushions, no pockets (isolated collisions).
    Open,
}

/// A straight cushion nose (or a pocket facing): the ball touches it when its centre is
/// [`crate::params::Params::cushion_contact_distance`] from the line, on the `normal` side.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Cushion {
    /// Name used in results ("baulk", "top-right/top facing", ...).
    pub name: String,
    /// One end of the nose line (plan, z = 0).
    pub start: Vec3,
    /// The other end.
    pub end: Vec3,
    /// Unit normal pointing to the side balls are on.
    pub normal: Vec3,
}

impl Cushion {
    /// Length of the segment.
    pub fn length(&self) -> f64 {
        (self.end - self.start).norm()
    }

    /// Unit vector from `start` to `end`.
    pub fn direction(&self) -> Vec3 {
        (self.end - self.start).normalize()
    }
}

/// A pocket jaw ("knuckle"): the rounded end of a cushion nose, an arc of radius `radius`
/// around `centre` at the nose height. A ball touches it when its centre is
/// `radius + R cos(theta)` from `centre` in plan.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Jaw {
    /// Name used in results.
    pub name: String,
    /// Centre of the arc (plan).
    pub centre: Vec3,
    /// Radius of the arc, m.
    pub radius: f64,
}

/// A pocket: a ball is captured when its centre enters the fall circle.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Pocket {
    /// Name ("top-left", "middle-right", ...).
    pub name: String,
    /// Centre of the fall circle (plan).
    pub centre: Vec3,
    /// Radius of the fall circle, m.
    pub radius: f64,
    /// Middle of the mouth, between the two jaws (plan).
    pub mouth: Vec3,
    /// Distance between the two jaw points, m.
    pub mouth_width: f64,
}

/// A table's geometry.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Table {
    /// Snooker or open.
    pub kind: TableKind,
    /// Playing-area length along x, m (0 for the open table).
    pub length: f64,
    /// Playing-area width along y, m (0 for the open table).
    pub width: f64,
    /// Straight noses and pocket facings.
    pub cushions: Vec<Cushion>,
    /// Jaw arcs.
    pub jaws: Vec<Jaw>,
    /// Pockets.
    pub pockets: Vec<Pocket>,
    /// Markings (baulk line, D, spots), for drawing.
    pub dims: Option<SnookerDims>,
}

/// How far from the origin a ball may be placed on the open table, m, in x and in y: the
/// cloth is endless, but far out a coordinate's rounding step nears the contact tolerance
/// ([`crate::detect::TOUCH_TOL`]) and two touching balls' gap is lost (at 1e15 m the step is
/// 0.125 m and an impact's normal speed comes out NaN). At 1 km the step is 1.1e-13 m.
pub const OPEN_EXTENT: f64 = 1000.0;

/// Shortest straight nose or facing a table may have, m: its direction is taken from its ends.
pub const MIN_NOSE_LENGTH: f64 = 1e-6;
/// How far a nose's normal may be from unit length and square to the nose (rounding).
const NORMAL_TOL: f64 = 1e-9;

impl Table {
    /// The endless cloth.
    pub fn open() -> Table {
        Table {
            kind: TableKind::Open,
            length: 0.0,
            width: 0.0,
            cushions: Vec::new(),
            jaws: Vec::new(),
            pockets: Vec::new(),
            dims: None,
        }
    }

    /// A full-size snooker table with the given dimensions.
    pub fn snooker(dims: &SnookerDims) -> Table {
        snooker::build(dims)
    }

    /// Why the engine cannot play on this table, if it cannot: the field at fault (as
    /// `cushions[3].normal`) and the reason. A table built by [`Table::snooker`] or
    /// [`Table::open`] always passes; one put together by hand must have every number finite,
    /// every point in plan (z = 0) and within [`OPEN_EXTENT`] of the origin, straight noses
    /// of some length with a unit normal across them, jaw radii not negative, pockets with a
    /// fall and a mouth, and playing-area sides not negative (positive on a snooker table).
    pub fn geometry_error(&self) -> Option<(String, String)> {
        let length = |field: &str, v: f64, least: f64| {
            (!(v.is_finite() && v >= least && v <= OPEN_EXTENT)).then(|| {
                let at_least = if least > 0.0 {
                    "positive"
                } else {
                    "not negative"
                };
                (
                    field.to_string(),
                    format!(
                        "must be a finite length in metres, {at_least} and at most \
                         {OPEN_EXTENT}, got {}",
                        Shown(v)
                    ),
                )
            })
        };
        let point = |field: String, p: Vec3| {
            let off = !p.iter().all(|x| x.is_finite())
                || p.x.abs() > OPEN_EXTENT
                || p.y.abs() > OPEN_EXTENT
                || p.z != 0.0;
            off.then(|| {
                (
                    field,
                    format!(
                        "must be a plan point (z = 0) within {OPEN_EXTENT} m of the origin, got \
                         ({}, {}, {})",
                        Shown(p.x),
                        Shown(p.y),
                        Shown(p.z)
                    ),
                )
            })
        };
        let least_side = if self.kind == TableKind::Snooker {
            f64::MIN_POSITIVE
        } else {
            0.0
        };
        if let Some(e) = length("length", self.length, least_side)
            .or_else(|| length("width", self.width, least_side))
        {
            return Some(e);
        }
        for (i, c) in self.cushions.iter().enumerate() {
            let at = |key: &str| format!("cushions[{i}].{key}");
            if let Some(e) = point(at("start"), c.start).or_else(|| point(at("end"), c.end)) {
                return Some(e);
            }
            if c.length() < MIN_NOSE_LENGTH {
                return Some((
                    at("end"),
                    format!(
                        "the nose \"{}\" must be at least {MIN_NOSE_LENGTH} m long, got {}",
                        c.name,
                        Shown(c.length())
                    ),
                ));
            }
            let n = c.normal;
            let unit = n.iter().all(|x| x.is_finite())
                && n.z == 0.0
                && (n.norm() - 1.0).abs() <= NORMAL_TOL
                && n.dot(&c.direction()).abs() <= NORMAL_TOL;
            if !unit {
                return Some((
                    at("normal"),
                    format!(
                        "the nose \"{}\" needs a unit normal in plan across its line, got ({}, \
                         {}, {})",
                        c.name,
                        Shown(n.x),
                        Shown(n.y),
                        Shown(n.z)
                    ),
                ));
            }
        }
        for (i, j) in self.jaws.iter().enumerate() {
            let at = |key: &str| format!("jaws[{i}].{key}");
            if let Some(e) =
                point(at("centre"), j.centre).or_else(|| length(&at("radius"), j.radius, 0.0))
            {
                return Some(e);
            }
        }
        for (i, p) in self.pockets.iter().enumerate() {
            let at = |key: &str| format!("pockets[{i}].{key}");
            if let Some(e) = point(at("centre"), p.centre)
                .or_else(|| point(at("mouth"), p.mouth))
                .or_else(|| length(&at("radius"), p.radius, f64::MIN_POSITIVE))
                .or_else(|| length(&at("mouth_width"), p.mouth_width, f64::MIN_POSITIVE))
            {
                return Some(e);
            }
        }
        None
    }

    /// Why a ball of radius `radius` cannot rest with its centre at `pos` (plan), if it can't:
    /// off the playing area, touching into a cushion or jaw, or over a pocket.
    /// `contact` is the centre's distance to a nose when touching it (R cos theta).
    pub fn placement_error(&self, pos: Vec3, contact: f64) -> Option<String> {
        if self.kind == TableKind::Open {
            if pos.x.abs() > OPEN_EXTENT || pos.y.abs() > OPEN_EXTENT {
                return Some(format!(
                    "centre ({:.4}, {:.4}) m is beyond the open cloth's extent: a ball's centre \
                     must lie within {OPEN_EXTENT} m of the origin in x and in y (further out, \
                     positions are too coarse for the contacts to be resolved)",
                    Shown(pos.x),
                    Shown(pos.y)
                ));
            }
            return None;
        }
        let tol = crate::detect::TOUCH_TOL;
        let (lo_x, hi_x) = (contact, self.length - contact);
        let (lo_y, hi_y) = (contact, self.width - contact);
        let outside =
            pos.x < lo_x - tol || pos.x > hi_x + tol || pos.y < lo_y - tol || pos.y > hi_y + tol;
        if outside && !self.in_mouth(pos, contact) {
            return Some(format!(
                "centre ({:.4}, {:.4}) m is off the cloth: a ball's centre must lie in \
                 [{lo_x:.4}, {hi_x:.4}] x [{lo_y:.4}, {hi_y:.4}] m (R cos(theta) from the cushion noses), \
                 or between a pocket's jaws short of its fall",
                Shown(pos.x),
                Shown(pos.y)
            ));
        }
        for jaw in &self.jaws {
            if (pos - jaw.centre).norm() < jaw.radius + contact - tol {
                return Some(format!("the ball overlaps the jaw {}", jaw.name));
            }
        }
        for pocket in &self.pockets {
            if (pos - pocket.centre).norm() < pocket.radius {
                return Some(format!("the ball is over the {} pocket", pocket.name));
            }
        }
        None
    }

    /// True when a ball centred at `pos` (plan) rests between a pocket's jaws, beyond the
    /// line of the noses but short of the fall: on the bed of the pocket's mouth, clear of
    /// every nose and facing along its length (where a shot can leave a ball: WPBSA Section 3
    /// Rule 9, a ball on the edge of a pocket). The jaws and falls are checked apart.
    ///
    /// "Between the jaws" is within [`Pocket::opening_reach`] of the mouth's middle, as
    /// [`Table::holds`] has it (a deep fall's shelf included: the engine can leave a ball at
    /// rest there, so a scene can place one). "Short of the fall" is [`Pocket::short_of_back`]: a centre past the fall's diameter
    /// across the pocket's axis is behind the hole, over the pocket's back, where no ball can
    /// rest (one on the cloth that gets there has crossed the fall and dropped; one in the air
    /// has left the table, `detect::pocket`), so it is refused like any centre off the cloth.
    fn in_mouth(&self, pos: Vec3, contact: f64) -> bool {
        let tol = crate::detect::TOUCH_TOL;
        let near = self
            .pockets
            .iter()
            .any(|p| (pos - p.mouth).norm() <= p.opening_reach() && p.short_of_back(pos, 0.0));
        near && self.cushions.iter().all(|c| {
            let s = (pos - c.start).dot(&c.direction());
            let along = s >= 0.0 && s <= c.length();
            !along || c.normal.dot(&(pos - c.start)) >= contact - tol
        })
    }

    /// True when a ball centre at `pos` (plan) is on the playing surface, `contact` or more
    /// inside the nose lines, or in a pocket's opening (within the mouth's width, and the fall's
    /// depth behind it, of the mouth's middle), up to `tol` metres: where a ball in play may be
    /// found during a shot.
    pub fn holds(&self, pos: Vec3, contact: f64, tol: f64) -> bool {
        if self.kind == TableKind::Open {
            return true;
        }
        let inside = pos.x >= contact - tol
            && pos.x <= self.length - contact + tol
            && pos.y >= contact - tol
            && pos.y <= self.width - contact + tol;
        let plan = Vec3::new(pos.x, pos.y, 0.0);
        inside
            || self.pockets.iter().any(|p| {
                let opening = (plan - p.mouth).norm() <= p.opening_reach() + tol;
                // Over the fall (a ball in the air), or in front of its far half.
                opening
                    && ((plan - p.centre).norm() <= p.radius + tol || p.short_of_back(plan, tol))
            })
    }
}

impl Pocket {
    /// How far from the mouth's middle (plan) a ball's centre can be and still be in the
    /// pocket's opening: the mouth's width and the fall's depth behind it.
    pub fn opening_reach(&self) -> f64 {
        let deep = (self.centre - self.mouth).norm() - self.radius;
        self.mouth_width + deep.max(0.0)
    }

    /// How far from the mouth's middle (plan) the pocket's back is looked for: the opening's
    /// reach and a mouth's width more (the facings, which reach past the back, confine a ball
    /// on the cloth to less; `detect::pocket::back_time`).
    pub fn back_reach(&self) -> f64 {
        self.opening_reach() + self.mouth_width
    }

    /// The unit vector along the pocket's axis, from the mouth into the pocket (plan).
    pub fn axis(&self) -> Vec3 {
        (self.centre - self.mouth)
            .try_normalize(0.0)
            .unwrap_or_else(Vec3::zeros)
    }

    /// True when the plan point `pos` is not past the fall's diameter across the pocket's axis
    /// (up to `tol` metres): in front of the far half of the fall, where the pocket's back
    /// begins (the engine's model of the back: `detect::pocket`, README Table section).
    pub fn short_of_back(&self, pos: Vec3, tol: f64) -> bool {
        let plan = Vec3::new(pos.x, pos.y, 0.0);
        (plan - self.centre).dot(&self.axis()) <= tol
    }
}
