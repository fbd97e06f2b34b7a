//! Ball-cushion contact. The nose is an edge at height h (7R/5) above the cloth: a ball touches
//! it when its centre is R from the edge. On the cloth (centre at height R) that is R cos(theta)
//! from the nose line in plan (thesis §6.2), and r_j + R cos(theta) from a jaw arc's centre.
//! A ball in the air touches the edge wherever its centre passes within R of it: from below
//! the nose's height or above it (a ball dropping onto a cushion, thesis §6.1.6's hop meeting
//! one). A ball whose lowest point is above the nose when its centre crosses the nose line
//! clears the cushion and leaves the table.

use super::roots::{entries, first_entry, line_contacts, ring_entries};
use super::{TOUCH_TOL, VERIFY_TOL};
use crate::motion::Path;
use crate::table::{Cushion, Jaw};

/// The height of the nose edges above the cloth and the ball radius: what a ball in the air
/// meets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NoseEdge {
    /// Height of the nose above the cloth, m.
    pub height: f64,
    /// Ball radius, m.
    pub radius: f64,
}

impl NoseEdge {
    /// Whether a ball centred at height `z` has its lowest point at or above the nose (within
    /// the detection's tolerance): it clears a cushion's nose, a jaw and a pocket's back.
    pub fn cleared_at(&self, z: f64) -> bool {
        z - self.radius >= self.height - VERIFY_TOL
    }
}

/// True when the plan point `at` lies along `cushion` (within its length).
fn along(cushion: &Cushion, at: crate::ball::Vec3) -> bool {
    let s = (at - cushion.start).dot(&cushion.direction());
    s >= -TOUCH_TOL && s <= cushion.length() + TOUCH_TOL
}

/// First time in [0, window] at which a ball in the air on `path` touches the nose edge of the
/// straight `cushion`, approaching it, from the table's side and within the cushion's length.
/// In the vertical plane across the nose, the centre's (plan distance, height above the nose)
/// enters the circle of radius R around the edge.
pub fn nose_time_in_air(
    path: &Path,
    cushion: &Cushion,
    edge: NoseEdge,
    window: f64,
) -> Option<f64> {
    let n = cushion.normal;
    let across = |v: crate::ball::Vec3, z: f64| crate::ball::Vec3::new(n.dot(&v), z, 0.0);
    let rel = Path {
        c: across(path.c - cushion.start, path.c.z - edge.height),
        b: across(path.b, path.b.z),
        a: across(path.a, path.a.z),
    };
    entries(&rel, edge.radius, window).find(|&t| {
        let at = path.at(t);
        n.dot(&(at - cushion.start)) > 0.0 && along(cushion, at)
    })
}

/// First time in [0, window] at which a ball in the air on `path` passes over the nose line
/// of `cushion` (within its length) with its lowest point above the nose: it clears the
/// cushion and leaves the table.
pub fn over_time(path: &Path, cushion: &Cushion, edge: NoseEdge, window: f64) -> Option<f64> {
    let plan = path.plan();
    let (t, _) = line_contacts(&plan, cushion.start, cushion.normal, 0.0, window)
        .find(|&(_, at)| along(cushion, at))?;
    edge.cleared_at(path.at(t).z).then_some(t)
}

/// First time in [0, window] at which a ball in the air on `path` touches the rounded edge of
/// the `jaw` (a ring of the jaw's radius at the nose's height), approaching it.
pub fn jaw_time_in_air(path: &Path, jaw: &Jaw, edge: NoseEdge, window: f64) -> Option<f64> {
    let mut rel = path.plan();
    rel.c -= jaw.centre;
    let dz = [path.c.z - edge.height, path.b.z, path.a.z];
    if jaw.radius > 0.0 {
        ring_entries(&rel, dz, jaw.radius, edge.radius, window).next()
    } else {
        // A sharp jaw: a point at the nose's height.
        let mut point = *path;
        point.c -= jaw.centre + crate::ball::Vec3::new(0.0, 0.0, edge.height);
        first_entry(&point, edge.radius, window)
    }
}

/// First time in [0, window] at which a ball in the air on `path` passes over the rounded
/// edge of `jaw` with its lowest point above the nose: its centre enters the jaw's arc in
/// plan (the cushion's body, behind the nose and the facing the arc joins) and it clears the
/// cushion there, leaving the table. A ball entering it lower has touched the edge before.
/// A sharp jaw (radius 0) is the meeting point of the nose and the facing, which
/// [`over_time`] covers.
pub fn over_jaw_time(path: &Path, jaw: &Jaw, edge: NoseEdge, window: f64) -> Option<f64> {
    if jaw.radius <= 0.0 {
        return None;
    }
    let mut rel = path.plan();
    rel.c -= jaw.centre;
    let t = first_entry(&rel, jaw.radius, window)?;
    edge.cleared_at(path.at(t).z).then_some(t)
}

/// First time in [0, window] at which `path` touches the straight `cushion` within its
/// length, approaching it; `contact` is R cos(theta).
pub fn nose_time(path: &Path, cushion: &Cushion, contact: f64, window: f64) -> Option<f64> {
    let plan = path.plan();
    line_contacts(&plan, cushion.start, cushion.normal, contact, window)
        .find(|&(_, at)| along(cushion, at))
        .map(|(t, _)| t)
}

/// First time in [0, window] at which `path` touches the `jaw` arc, approaching it.
pub fn jaw_time(path: &Path, jaw: &Jaw, contact: f64, window: f64) -> Option<f64> {
    let mut rel = path.plan();
    rel.c -= jaw.centre;
    first_entry(&rel, jaw.radius + contact, window)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Vec3;

    #[test]
    fn misses_beyond_the_end_of_the_nose() {
        let cushion = Cushion {
            name: "c".into(),
            start: Vec3::new(0.0, 0.0, 0.0),
            end: Vec3::new(1.0, 0.0, 0.0),
            normal: Vec3::y(),
        };
        let toward = |x: f64| Path {
            c: Vec3::new(x, 0.5, 0.0),
            b: Vec3::new(0.0, -1.0, 0.0),
            a: Vec3::zeros(),
        };
        assert!(nose_time(&toward(0.5), &cushion, 0.024, 1.0).is_some());
        assert!(nose_time(&toward(1.1), &cushion, 0.024, 1.0).is_none());
    }

    /// Fuzz scene 420183 (seed 20261128): a red thrown from mid-table over the top-right
    /// corner, coming down onto the top cushion's jaw 2.7 m and 0.62 s from where its flight
    /// began. Its centre passes 2 mm from the jaw's edge (0.024 m inside the touching
    /// distance), yet the contact was not found: the octic's root, expanded about the flight's
    /// start, is off by ~1e-8 s, ~1e-7 m, and failed the 1e-9 m check, so the red landed on the
    /// cushion's body and rolled off the end of the world.
    #[test]
    fn a_ball_coming_down_onto_a_jaw_from_far_away_meets_it() {
        let p = crate::params::Params::default();
        let table = crate::table::Table::snooker(&Default::default());
        let jaw = table
            .jaws
            .iter()
            .find(|j| j.name == "top-right/top jaw")
            .unwrap();
        let g = p.g;
        let path = Path {
            c: Vec3::new(
                0.897_861_608_416_986,
                0.304_817_902_073_025_06,
                p.ball_radius,
            ),
            b: Vec3::new(
                4.252_456_216_072_619,
                -0.395_041_506_300_891_47,
                3.105_753_587_054_569_4,
            ),
            a: Vec3::new(0.0, 0.0, -0.5 * g),
        };
        let edge = NoseEdge {
            height: p.cushion_height,
            radius: p.ball_radius,
        };
        let t = jaw_time_in_air(&path, jaw, edge, 0.64).expect("the jaw is met");
        assert!((0.62..0.627).contains(&t), "{t}");
        let at = path.at(t);
        let d = (Vec3::new(at.x, at.y, 0.0) - jaw.centre).norm() - jaw.radius;
        let touch = d.hypot(at.z - edge.height);
        assert!((touch - edge.radius).abs() < 1e-9, "{touch}");
    }
}
