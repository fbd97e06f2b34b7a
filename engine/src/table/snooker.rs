//! A full-size snooker table.
//!
//! Frame (formats.md): origin at a baulk-end corner of the playing area, x along the long side
//! towards the black spot, y across, z up, right-handed. Drawn in plan with the baulk end on
//! the left and y up the page, the origin is the bottom-left corner; for a player standing
//! behind the baulk line it is the corner on their right, so y grows towards the player's left
//! and the yellow spot (on the player's right, WPBSA rules) has the smaller y.
//!
//! Dimensions: WPBSA Official Rules §1 (playing area 3569 x 1778 mm, baulk line 737 mm from
//! the baulk cushion face, D radius 292 mm, black spot 324 mm from the top cushion face, pink
//! midway between the centre spot and the top cushion). The WPBSA pocket templates are not
//! public: the pocket openings are the thesis's 90 mm for all six (thesis §8.5); jaw radius,
//! facing angles and fall position are stated assumptions, documented in docs/physics.md.

use super::{Cushion, Jaw, Pocket, Table, TableKind};
use crate::ball::Vec3;
use serde::{Deserialize, Serialize};

/// Dimensions of a snooker table, m and rad.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SnookerDims {
    /// Playing-area length between the cushion noses (WPBSA: 3569 mm).
    pub length: f64,
    /// Playing-area width between the cushion noses (WPBSA: 1778 mm).
    pub width: f64,
    /// Baulk line, distance from the baulk cushion nose (WPBSA: 737 mm).
    pub baulk_line: f64,
    /// Radius of the D (WPBSA: 292 mm).
    pub d_radius: f64,
    /// Black spot, distance from the top cushion nose (WPBSA: 324 mm).
    pub black_from_top: f64,
    /// Corner pocket opening between the jaw points (thesis §8.5: 90 mm).
    pub corner_mouth: f64,
    /// Middle pocket opening between the jaw points (thesis §8.5: 90 mm).
    pub middle_mouth: f64,
    /// Radius of the rounded jaw that joins a nose to its facing. Assumption: 10 mm.
    pub jaw_radius: f64,
    /// Angle between a corner pocket's facing and the nose it continues. Assumption: 37 deg
    /// (an entry angle of 143 deg, typical of snooker corner pockets).
    pub corner_facing_angle: f64,
    /// Same for a middle pocket. Assumption: 78 deg (entry angle 102 deg).
    pub middle_facing_angle: f64,
    /// Length of each facing, m: at least this, and lengthened where a wide mouth or a deep
    /// fall needs it to reach [`FACING_PAST_BACK`] past the fall's back (its diameter across
    /// the pocket's axis), so that the facings close the opening up to the pocket's back.
    pub facing_length: f64,
    /// How far behind the line joining the jaw points the fall circle begins, m.
    /// Assumption: 0 (a ball drops once its centre is past the mouth and inside the fall).
    pub fall_depth: f64,
}

impl Default for SnookerDims {
    fn default() -> Self {
        SnookerDims {
            length: 3.569,
            width: 1.778,
            baulk_line: 0.737,
            d_radius: 0.292,
            black_from_top: 0.324,
            corner_mouth: 0.090,
            middle_mouth: 0.090,
            jaw_radius: 0.010,
            corner_facing_angle: 37f64.to_radians(),
            middle_facing_angle: 78f64.to_radians(),
            facing_length: 0.15,
            fall_depth: 0.0,
        }
    }
}

/// A named spot (plan position).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spot {
    /// "black", "pink", "blue", "brown", "yellow", "green".
    pub name: &'static str,
    /// Position (z = 0).
    pub pos: Vec3,
}

impl SnookerDims {
    /// The six colour spots (WPBSA rules §1(f)).
    pub fn spots(&self) -> [Spot; 6] {
        let (l, w) = (self.length, self.width);
        let spot = |name, x, y| Spot {
            name,
            pos: Vec3::new(x, y, 0.0),
        };
        [
            spot("yellow", self.baulk_line, w / 2.0 - self.d_radius),
            spot("green", self.baulk_line, w / 2.0 + self.d_radius),
            spot("brown", self.baulk_line, w / 2.0),
            spot("blue", l / 2.0, w / 2.0),
            spot("pink", 0.75 * l, w / 2.0),
            spot("black", l - self.black_from_top, w / 2.0),
        ]
    }

    /// The spot of the named colour.
    pub fn spot(&self, name: &str) -> Option<Vec3> {
        self.spots().iter().find(|s| s.name == name).map(|s| s.pos)
    }
}

/// One end of a cushion nose at a pocket: the jaw point, the direction along the nose towards
/// the pocket and the nose's normal into the table.
struct JawEnd {
    point: Vec3,
    toward_pocket: Vec3,
    normal: Vec3,
    cushion: &'static str,
}

fn v(x: f64, y: f64) -> Vec3 {
    Vec3::new(x, y, 0.0)
}

/// How far past the fall's back (along the pocket's axis) the facings reach at least, m: more
/// than any ball's radius the scenes allow (40 mm), so that a ball beside the fall meets the
/// pocket's back (`detect::pocket::back_time`) before it can pass a facing's end. Before, a
/// pocket with a wide mouth and a deep fall left a gap there, and a ball rolled out through it
/// onto cloth that is not there.
pub const FACING_PAST_BACK: f64 = 0.05;

/// Builds a pocket from its two jaw ends: jaw arcs tangent to the noses, facings tangent to
/// the arcs turned by `facing_angle`, and the fall circle behind the mouth.
fn pocket(name: &str, ends: [JawEnd; 2], facing_angle: f64, dims: &SnookerDims, table: &mut Table) {
    let r = dims.jaw_radius;
    let mouth = 0.5 * (ends[0].point + ends[1].point);
    let mouth_width = (ends[0].point - ends[1].point).norm();
    let axis = -(ends[0].normal + ends[1].normal).normalize();
    // The depth behind the mouth the facings must reach: the fall's back and the margin.
    let back = dims.fall_depth + 0.5 * mouth_width + FACING_PAST_BACK;
    for end in &ends {
        let centre = end.point - r * end.normal;
        let facing_dir = facing_angle.cos() * end.toward_pocket - facing_angle.sin() * end.normal;
        let facing_normal =
            facing_angle.sin() * end.toward_pocket + facing_angle.cos() * end.normal;
        let start = centre + r * facing_normal;
        let along = facing_dir.dot(&axis);
        let needed = if along > 0.0 {
            (back - (start - mouth).dot(&axis)) / along
        } else {
            0.0
        };
        table.jaws.push(Jaw {
            name: format!("{name}/{} jaw", end.cushion),
            centre,
            radius: r,
        });
        table.cushions.push(Cushion {
            name: format!("{name}/{} facing", end.cushion),
            start,
            end: start + dims.facing_length.max(needed) * facing_dir,
            normal: facing_normal,
        });
    }
    let radius = 0.5 * mouth_width;
    table.pockets.push(Pocket {
        name: name.to_string(),
        centre: mouth + (dims.fall_depth + radius) * axis,
        radius,
        mouth,
        mouth_width,
    });
}

/// Builds the snooker table (see the module docs for the frame and sources).
pub fn build(dims: &SnookerDims) -> Table {
    let (l, w) = (dims.length, dims.width);
    let c = dims.corner_mouth / std::f64::consts::SQRT_2;
    let m = 0.5 * dims.middle_mouth;
    let mut table = Table {
        kind: TableKind::Snooker,
        length: l,
        width: w,
        cushions: Vec::new(),
        jaws: Vec::new(),
        pockets: Vec::new(),
        dims: Some(*dims),
    };
    let nose = |name: &str, a: Vec3, b: Vec3, n: Vec3| Cushion {
        name: name.to_string(),
        start: a,
        end: b,
        normal: n,
    };
    // y = 0 is on the right of a player standing behind the baulk line.
    table.cushions.extend([
        nose("baulk", v(0.0, c), v(0.0, w - c), v(1.0, 0.0)),
        nose("top", v(l, c), v(l, w - c), v(-1.0, 0.0)),
        nose("right-baulk", v(c, 0.0), v(l / 2.0 - m, 0.0), v(0.0, 1.0)),
        nose("right-top", v(l / 2.0 + m, 0.0), v(l - c, 0.0), v(0.0, 1.0)),
        nose("left-baulk", v(c, w), v(l / 2.0 - m, w), v(0.0, -1.0)),
        nose("left-top", v(l / 2.0 + m, w), v(l - c, w), v(0.0, -1.0)),
    ]);
    // Corner pockets: (corner, pocket name, long cushion, end cushion).
    let corners = [
        (v(0.0, 0.0), "baulk-right", "right-baulk", "baulk"),
        (v(0.0, w), "baulk-left", "left-baulk", "baulk"),
        (v(l, 0.0), "top-right", "right-top", "top"),
        (v(l, w), "top-left", "left-top", "top"),
    ];
    for (k, name, side, end) in corners {
        let sx = if k.x == 0.0 { 1.0 } else { -1.0 };
        let sy = if k.y == 0.0 { 1.0 } else { -1.0 };
        let ends = [
            JawEnd {
                point: k + v(sx * c, 0.0),
                toward_pocket: v(-sx, 0.0),
                normal: v(0.0, sy),
                cushion: side,
            },
            JawEnd {
                point: k + v(0.0, sy * c),
                toward_pocket: v(0.0, -sy),
                normal: v(sx, 0.0),
                cushion: end,
            },
        ];
        pocket(name, ends, dims.corner_facing_angle, dims, &mut table);
    }
    let middles = [
        (0.0, 1.0, "middle-right", ["right-top", "right-baulk"]),
        (w, -1.0, "middle-left", ["left-top", "left-baulk"]),
    ];
    for (y, sy, name, [top_side, baulk_side]) in middles {
        let ends = [
            JawEnd {
                point: v(l / 2.0 + m, y),
                toward_pocket: v(-1.0, 0.0),
                normal: v(0.0, sy),
                cushion: top_side,
            },
            JawEnd {
                point: v(l / 2.0 - m, y),
                toward_pocket: v(1.0, 0.0),
                normal: v(0.0, sy),
                cushion: baulk_side,
            },
        ];
        pocket(name, ends, dims.middle_facing_angle, dims, &mut table);
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn geometry_is_closed_and_tangent() {
        let dims = SnookerDims::default();
        let t = build(&dims);
        assert_eq!(t.pockets.len(), 6);
        assert_eq!(t.jaws.len(), 12);
        assert_eq!(t.cushions.len(), 6 + 12);
        for p in &t.pockets {
            assert!((p.mouth_width - 0.090).abs() < 1e-12, "{}", p.name);
        }
        // Every jaw arc is tangent to a nose end: one nose endpoint lies on each arc, with the
        // nose normal pointing away from the arc centre.
        for jaw in &t.jaws {
            let touching = t
                .cushions
                .iter()
                .filter(|c| !c.name.contains("facing"))
                .any(|c| {
                    [c.start, c.end].iter().any(|e| {
                        ((e - jaw.centre).norm() - jaw.radius).abs() < 1e-12
                            && ((e - jaw.centre).normalize() - c.normal).norm() < 1e-12
                    })
                });
            assert!(touching, "{}", jaw.name);
        }
        // Facings start on their jaw arc and point into the pocket, their normals facing the mouth.
        for p in &t.pockets {
            let facings: Vec<_> = t
                .cushions
                .iter()
                .filter(|c| c.name.starts_with(&format!("{}/", p.name)))
                .collect();
            assert_eq!(facings.len(), 2);
            for f in facings {
                assert!((f.end - p.centre).norm() < (f.start - p.centre).norm() + 0.1);
                assert!(f.normal.dot(&(p.mouth - f.start)) > 0.0, "{}", f.name);
            }
        }
    }

    #[test]
    fn a_ball_may_rest_in_a_pockets_mouth_but_not_in_a_cushion_jaw_or_fall() {
        // Where random strokes left balls at rest (found by the rules crate's property test):
        // between the jaws, beyond the line of the noses, short of the fall.
        let t = build(&SnookerDims::default());
        let p = crate::Params::default();
        let contact = p.cushion_contact_distance();
        for (x, y) in [(1.7834, 1.7704), (1.7898, 0.0192), (0.0217, 0.0439)] {
            let at = Vec3::new(x, y, 0.0);
            assert_eq!(t.placement_error(at, contact), None, "({x}, {y})");
            // A shot from there runs: a ball struck into the pocket falls.
            let ball = crate::Ball {
                id: "red".into(),
                kind: crate::BallKind::Red,
                state: crate::BallState {
                    vel: (t
                        .pockets
                        .iter()
                        .min_by(|a, b| (a.centre - at).norm().total_cmp(&(b.centre - at).norm())))
                    .map(|k| (k.centre - at).normalize() * 0.3)
                    .unwrap(),
                    ..crate::BallState::at_rest(x, y, p.ball_radius)
                },
            };
            let setup = crate::Setup {
                table: t.clone(),
                params: p,
                models: Default::default(),
                balls: vec![ball],
            };
            setup.validate().unwrap();
            let shot = crate::simulate(&setup, &Default::default()).unwrap();
            assert_eq!(shot.final_states()[0].motion, crate::Motion::Pocketed);
        }
        // Beyond the noses away from a mouth; into a jaw; over a fall: refused.
        for (x, y) in [(1.0, 1.77), (1.7845 + 0.045, 1.77), (1.7845, 1.79)] {
            assert!(
                t.placement_error(Vec3::new(x, y, 0.0), contact).is_some(),
                "({x}, {y})"
            );
        }
    }

    #[test]
    fn spots_follow_the_rules() {
        let d = SnookerDims::default();
        assert!((d.spot("pink").unwrap().x - 2.67675).abs() < 1e-9);
        assert!((d.spot("black").unwrap().x - 3.245).abs() < 1e-9);
        assert!(d.spot("yellow").unwrap().y < d.spot("green").unwrap().y);
    }
}
