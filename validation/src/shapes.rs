//! The table's features as the solid shapes rapier collides with, and the gap between a ball
//! and each of them.
//!
//! - Cushion noses and pocket facings: horizontal capsules placed so that a ball on the cloth
//!   touches them at height h = 7R/5 with the contact normal tilted by theta, sin(theta) =
//!   (h - R)/R (thesis §6.2): a capsule of radius r_c has its axis r_c cos(theta) behind the
//!   nose line and at height R + (R + r_c) sin(theta), so that the contact point lies on the
//!   nose line at height h and a ball touches when its centre is R cos(theta) from the line in
//!   plan, the engine's rule (physics.md).
//! - Jaws: spheres of radius r_j / cos(theta) centred R + (R + r_j / cos(theta)) sin(theta)
//!   above the jaw's centre: a ball on the cloth touches one at height h, r_j from the jaw
//!   centre in plan, when its centre is r_j + R cos(theta) away (the engine's rule). With
//!   r_c = r_j / cos(theta) a capsule's rounded end is exactly the jaw sphere at that end.
//!
//! [`ContactHeight::Level`] instead puts the noses and jaws at the height of the ball's centre,
//! with the same plan contact distances, so that the contact normal is horizontal: on a rigid
//! cloth and without friction this is the same impact (the nose's push through the centre plus
//! the cloth's reaction is a horizontal impulse through the centre either way), and it keeps
//! rapier's end-of-step restitution pass, which acts on one contact at a time, from losing the
//! vertical part of the bounce to the cloth (see docs/validation.md).
//! - Pockets: spheres of radius (fall radius - R) at the height of a ball's centre: a ball on
//!   the cloth overlaps one exactly when its centre is inside the fall circle in plan.

use snooker_engine::{Params, Table, Vec3};

/// Jaw radius used for nose capsules when a table has no jaws, m (the default table's 10 mm).
const DEFAULT_JAW_RADIUS: f64 = 0.010;

/// Where the cushions touch a ball.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ContactHeight {
    /// At the nose height h = 7R/5, normal tilted by theta (thesis §6.2).
    Nose,
    /// At the height of the ball's centre, normal horizontal (equivalent without friction).
    Level,
}

/// A capsule: the points within `radius` of the segment from `a` to `b`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Capsule {
    /// One end of the axis.
    pub a: Vec3,
    /// The other end.
    pub b: Vec3,
    /// Radius, m.
    pub radius: f64,
}

/// A sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// Centre.
    pub centre: Vec3,
    /// Radius, m.
    pub radius: f64,
}

/// A table feature a ball can hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Feature {
    /// Straight cushion `k` of the table (nose or facing).
    Cushion(usize),
    /// Jaw `k` of the table.
    Jaw(usize),
}

/// The table's features as solids.
#[derive(Clone, Debug, PartialEq)]
pub struct TableShapes {
    /// One per straight cushion, in the table's order.
    pub noses: Vec<Capsule>,
    /// One per jaw, in the table's order.
    pub jaws: Vec<Sphere>,
    /// One per pocket, in the table's order.
    pub pockets: Vec<Sphere>,
    ball_radius: f64,
}

/// Radius and centre height of the sphere (or capsule) that stands for a jaw arc of plan
/// radius `jaw_radius` (see the module docs).
pub fn jaw_solid(p: &Params, jaw_radius: f64, contact: ContactHeight) -> (f64, f64) {
    let s = p.cushion_sin_theta();
    let cos_t = (1.0 - s * s).sqrt();
    let r = p.ball_radius;
    match contact {
        ContactHeight::Nose => {
            let radius = jaw_radius / cos_t;
            (radius, r + (r + radius) * s)
        }
        // Touching when the centres are r_j + R cos(theta) apart in plan: R + radius.
        ContactHeight::Level => (jaw_radius - r * (1.0 - cos_t), r),
    }
}

/// The point of segment [a, b] nearest to `p`, and its parameter in [0, 1].
fn nearest_on_segment(a: Vec3, b: Vec3, p: Vec3) -> (Vec3, f64) {
    let ab = b - a;
    let len2 = ab.norm_squared();
    let s = if len2 > 0.0 {
        ((p - a).dot(&ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + s * ab, s)
}

impl TableShapes {
    /// The solids of `table` for balls of parameters `p`, touching them as `contact` says.
    pub fn new(table: &Table, p: &Params, contact: ContactHeight) -> TableShapes {
        let jaw_radius = table.jaws.first().map_or(DEFAULT_JAW_RADIUS, |j| j.radius);
        let (cap_r, cap_z) = jaw_solid(p, jaw_radius, contact);
        let lift = Vec3::new(0.0, 0.0, cap_z);
        let noses = table
            .cushions
            .iter()
            .map(|c| {
                // The axis lies behind the nose line as far as a jaw's centre: r_j.
                let back = -jaw_radius * c.normal;
                Capsule {
                    a: c.start + back + lift,
                    b: c.end + back + lift,
                    radius: cap_r,
                }
            })
            .collect();
        let jaws = table
            .jaws
            .iter()
            .map(|j| {
                let (radius, z) = jaw_solid(p, j.radius, contact);
                Sphere {
                    centre: j.centre + Vec3::new(0.0, 0.0, z),
                    radius,
                }
            })
            .collect();
        let pockets = table
            .pockets
            .iter()
            .map(|pk| Sphere {
                centre: pk.centre + Vec3::new(0.0, 0.0, p.ball_radius),
                radius: pk.radius - p.ball_radius,
            })
            .collect();
        TableShapes {
            noses,
            jaws,
            pockets,
            ball_radius: p.ball_radius,
        }
    }

    /// Gap between a ball centred at `pos` and `feature` (negative when they overlap), m, and
    /// the unit normal from the feature towards the ball.
    pub fn gap(&self, feature: Feature, pos: Vec3) -> (f64, Vec3) {
        let (point, radius) = match feature {
            Feature::Cushion(k) => {
                let c = &self.noses[k];
                (nearest_on_segment(c.a, c.b, pos).0, c.radius)
            }
            Feature::Jaw(k) => (self.jaws[k].centre, self.jaws[k].radius),
        };
        let d = pos - point;
        let dist = d.norm();
        (dist - radius - self.ball_radius, d / dist)
    }

    /// The feature a ball centred at `pos` is nearest to, with its gap and normal. A straight
    /// cushion counts only where the ball is abreast of it (beyond its ends the jaws take over,
    /// as in the engine).
    pub fn nearest(&self, pos: Vec3) -> Option<(Feature, f64, Vec3)> {
        let noses = (0..self.noses.len()).filter(|&k| {
            let c = &self.noses[k];
            let (_, s) = nearest_on_segment(c.a, c.b, pos);
            s > 0.0 && s < 1.0
        });
        noses
            .map(Feature::Cushion)
            .chain((0..self.jaws.len()).map(Feature::Jaw))
            .map(|f| {
                let (g, n) = self.gap(f, pos);
                (f, g, n)
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nose_contact_is_at_seven_fifths_r_and_r_cos_theta_in_plan() {
        let p = Params::default();
        let table = Table::snooker(&Default::default());
        let shapes = TableShapes::new(&table, &p, ContactHeight::Nose);
        let k = table
            .cushions
            .iter()
            .position(|c| c.name == "right-baulk")
            .unwrap();
        // A ball on the cloth R cos(theta) from the nose line (y = 0) just touches.
        let pos = Vec3::new(0.9, p.cushion_contact_distance(), p.ball_radius);
        let (gap, n) = shapes.gap(Feature::Cushion(k), pos);
        assert!(gap.abs() < 1e-15, "{gap}");
        // The contact point, R from the centre against the normal, is at height h on the line.
        let contact = pos - p.ball_radius * n;
        assert!((contact.z - p.cushion_height).abs() < 1e-15);
        assert!(contact.y.abs() < 1e-15);
        // The level contact touches at the same plan distance, with a horizontal normal.
        let level = TableShapes::new(&table, &p, ContactHeight::Level);
        let (gap, n) = level.gap(Feature::Cushion(k), pos);
        assert!(gap.abs() < 1e-15, "{gap}");
        assert!(n.z.abs() < 1e-15);
    }

    #[test]
    fn jaw_contact_follows_the_engine_rule() {
        let p = Params::default();
        let table = Table::snooker(&Default::default());
        let shapes = TableShapes::new(&table, &p, ContactHeight::Nose);
        let level = TableShapes::new(&table, &p, ContactHeight::Level);
        for (k, j) in table.jaws.iter().enumerate() {
            let dir = Vec3::new(0.6, 0.8, 0.0);
            let pos = j.centre
                + (j.radius + p.cushion_contact_distance()) * dir
                + Vec3::new(0.0, 0.0, p.ball_radius);
            let (gap, n) = shapes.gap(Feature::Jaw(k), pos);
            assert!(gap.abs() < 1e-15);
            let contact = pos - p.ball_radius * n;
            assert!((contact.z - p.cushion_height).abs() < 1e-15);
            let plan = Vec3::new(contact.x - j.centre.x, contact.y - j.centre.y, 0.0);
            assert!((plan.norm() - j.radius).abs() < 1e-15);
            assert!(level.gap(Feature::Jaw(k), pos).0.abs() < 1e-15);
        }
    }

    #[test]
    fn pocket_sphere_is_entered_with_the_centre_in_the_fall() {
        let p = Params::default();
        let table = Table::snooker(&Default::default());
        let shapes = TableShapes::new(&table, &p, ContactHeight::Nose);
        let pk = &table.pockets[0];
        let s = &shapes.pockets[0];
        let pos = pk.centre + Vec3::new(pk.radius, 0.0, p.ball_radius);
        assert!(((pos - s.centre).norm() - (s.radius + p.ball_radius)).abs() < 1e-15);
    }
}
