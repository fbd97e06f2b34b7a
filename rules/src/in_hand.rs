//! The cue ball in hand: the D, where it may be placed (on or within the lines of the D,
//! touching no ball: WPBSA Section 2 Rule 9 "In-hand", Section 3 Rule 5 "Playing from
//! In-hand"), and positions in it.

use crate::error::Problem;
use snooker_engine::{Ball, SnookerDims, Vec3};

/// How far outside its lines a point still counts as on the D, m: the rounding of the
/// coordinates, nothing a player could see.
pub const LINE_TOL: f64 = 1e-9;

/// The D: the semicircle in baulk with its centre at the middle of the baulk line (the brown
/// spot), behind the baulk line (WPBSA Section 1 Rule 1(e)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TheD {
    /// Its centre, the middle of the baulk line (plan, z = 0).
    pub centre: Vec3,
    /// Its radius, m (WPBSA: 292 mm).
    pub radius: f64,
}

impl TheD {
    /// The D of a table of these dimensions.
    pub fn of(dims: &SnookerDims) -> TheD {
        TheD {
            centre: Vec3::new(dims.baulk_line, dims.width / 2.0, 0.0),
            radius: dims.d_radius,
        }
    }

    /// True when a ball centred at `pos` (plan) is on or within the lines of the D, up to
    /// [`LINE_TOL`] (so that its corners, the yellow and green spots, are in it whatever the
    /// rounding of their coordinates).
    pub fn contains(&self, pos: Vec3) -> bool {
        let (dx, dy) = (pos.x - self.centre.x, pos.y - self.centre.y);
        dx <= LINE_TOL && (dx * dx + dy * dy).sqrt() <= self.radius + LINE_TOL
    }

    /// The point of the D nearest `pos` (itself if inside).
    pub fn nearest(&self, pos: Vec3) -> Vec3 {
        let mut d = Vec3::new((pos.x - self.centre.x).min(0.0), pos.y - self.centre.y, 0.0);
        let n = d.norm();
        if n > self.radius {
            d *= self.radius / n;
        }
        self.centre + d
    }

    /// Points of the D on a square grid `step` apart, the centre among them (z = 0), lazily:
    /// row by row from the baulk line back, each row from the centre line outwards
    /// alternately, so that a search stopping at its first success tries the middle first.
    /// A step below a thousandth of the radius (zero, negative or NaN: no grid at all) is
    /// taken as that thousandth (a zero step overflowed the grid's count).
    pub fn grid(&self, step: f64) -> impl Iterator<Item = Vec3> + '_ {
        let step = step.max(self.radius / 1000.0);
        let n = (self.radius / step).floor() as i64;
        (0..=n)
            .flat_map(move |i| {
                (0..=2 * n).map(move |j| {
                    let k = if j % 2 == 0 { -(j / 2) } else { j / 2 + 1 };
                    self.centre + Vec3::new(-(i as f64) * step, k as f64 * step, 0.0)
                })
            })
            .filter(move |&p| self.contains(p))
    }
}

/// Why the cue ball cannot be placed at `pos` (plan) when in hand, if it cannot: outside the D,
/// or touching a ball of `others` (centres 2R apart or closer).
pub fn placement_problem(d: &TheD, pos: Vec3, others: &[Ball], radius: f64) -> Option<Problem> {
    let pos = Vec3::new(pos.x, pos.y, 0.0);
    if !d.contains(pos) {
        return Some(Problem::OutsideD(pos));
    }
    let two_r = 2.0 * radius;
    others.iter().find_map(|b| {
        let gap = (b.state.pos.xy() - pos.xy()).norm();
        (gap <= two_r).then(|| Problem::Touching {
            pos,
            other: b.id.clone(),
            gap,
            two_r,
        })
    })
}

/// Grid spacing of [`nearest_placement`]'s search, m.
pub const PLACEMENT_STEP: f64 = 0.002;

/// The valid place for the cue ball in hand nearest `preferred` (plan): `preferred` itself if
/// valid, else the nearest point of the D, else the nearest point of a grid
/// [`PLACEMENT_STEP`] apart that is valid; `None` only if balls cover the whole D.
pub fn nearest_placement(d: &TheD, preferred: Vec3, others: &[Ball], radius: f64) -> Option<Vec3> {
    let preferred = Vec3::new(preferred.x, preferred.y, 0.0);
    let ok = |p: Vec3| placement_problem(d, p, others, radius).is_none();
    let near = d.nearest(preferred);
    if ok(near) {
        return Some(near);
    }
    d.grid(PLACEMENT_STEP)
        .filter(|&p| ok(p))
        .min_by(|a, b| (a - preferred).norm().total_cmp(&(b - preferred).norm()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use snooker_engine::{BallKind, BallState};

    #[test]
    fn the_d_is_the_semicircle_behind_the_baulk_line() {
        let d = TheD::of(&SnookerDims::default());
        assert_eq!((d.centre.x, d.centre.y, d.radius), (0.737, 0.889, 0.292));
        // The lines themselves belong to it (on or within).
        let dims = SnookerDims::default();
        for c in ["yellow", "green", "brown"] {
            assert!(d.contains(dims.spot(c).unwrap()), "{c}");
        }
        assert!(d.contains(Vec3::new(0.737 - 0.292, 0.889, 0.0)));
        assert!(!d.contains(Vec3::new(0.7371, 0.889, 0.0)));
        assert!(!d.contains(Vec3::new(0.5, 0.889 + 0.25, 0.0)));
        let g: Vec<Vec3> = d.grid(0.01).collect();
        assert!(g.iter().all(|&p| d.contains(p)));
        let mut distinct: Vec<(u64, u64)> =
            g.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect();
        distinct.sort_unstable();
        distinct.dedup();
        assert_eq!(distinct.len(), g.len());
        // pi r^2 / 2 = 0.1339 m^2: about 1339 points a centimetre apart.
        assert!(g.len() > 1300 && g.len() < 1380, "{}", g.len());
        assert_eq!(g[0], d.centre);
        // No step (zero, negative, NaN) is the finest grid, not an overflow.
        for step in [0.0, -1.0, f64::NAN] {
            assert_eq!(d.grid(step).next(), Some(d.centre), "{step}");
        }
    }

    #[test]
    fn placements_touching_a_ball_are_refused_and_the_nearest_free_one_found() {
        let d = TheD::of(&SnookerDims::default());
        let r = 0.02625;
        let brown = Ball {
            id: "brown".into(),
            kind: BallKind::Brown,
            state: BallState::at_rest(0.737, 0.889, r),
        };
        let others = [brown];
        let p = Vec3::new(0.737 - 2.0 * r, 0.889, 0.0);
        assert!(matches!(
            placement_problem(&d, p, &others, r),
            Some(Problem::Touching { .. })
        ));
        let q = nearest_placement(&d, p, &others, r).unwrap();
        assert!(placement_problem(&d, q, &others, r).is_none());
        assert!((q - p).norm() < PLACEMENT_STEP * 1.5, "{q:?}");
        let far = nearest_placement(&d, Vec3::new(2.0, 0.2, 0.0), &others, r).unwrap();
        assert!(d.contains(far));
    }
}
