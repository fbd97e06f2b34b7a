//! A broad phase for the table's features: the plan-view box a ball's path stays in over a
//! window, computed once per ball and event, so that a cushion, jaw or pocket the box is
//! clearly away from is not searched at all. A feature is skipped only when no contact could
//! be accepted with it (the box is exact, then widened by `SLACK` and by rounding), so
//! culling changes no result.

use super::VERIFY_TOL;
use crate::ball::Vec3;
use crate::motion::Path;

/// Widening of the box beyond the contact tests' tolerances, m.
const SLACK: f64 = 1e3 * VERIFY_TOL;

/// The plan-view box (x and y) a path stays in over [0, window], widened by `SLACK` and
/// the rounding of the path's numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanBox {
    lo: [f64; 2],
    hi: [f64; 2],
}

impl PlanBox {
    /// The box of `path` over [0, `window`] (`window` finite and non-negative; otherwise the
    /// whole plane).
    pub fn of(path: &Path, window: f64) -> PlanBox {
        if !(window.is_finite() && window >= 0.0) {
            return PlanBox {
                lo: [f64::NEG_INFINITY; 2],
                hi: [f64::INFINITY; 2],
            };
        }
        let widen = SLACK + 1e-9 * path.size(window);
        let mut lo = [0.0; 2];
        let mut hi = [0.0; 2];
        for k in 0..2 {
            // c + b t + a t^2 is extreme at the ends and where its rate vanishes.
            let (c, b, a) = (path.c[k], path.b[k], path.a[k]);
            let end = c + (b + a * window) * window;
            let (mut min, mut max) = (c.min(end), c.max(end));
            if a != 0.0 {
                let t = -b / (2.0 * a);
                if t > 0.0 && t < window {
                    let v = c + (b + a * t) * t;
                    min = min.min(v);
                    max = max.max(v);
                }
            }
            lo[k] = min - widen;
            hi[k] = max + widen;
        }
        PlanBox { lo, hi }
    }

    /// The box from corner `lo` to corner `hi` (x, y).
    pub fn new(lo: [f64; 2], hi: [f64; 2]) -> PlanBox {
        PlanBox { lo, hi }
    }

    /// Whether the box is not empty (each low corner at or below the high one).
    pub fn lo_below_hi(&self) -> bool {
        (0..2).all(|k| self.lo[k] <= self.hi[k])
    }

    /// Whether `other` lies within this box. The tests below are monotone: a box within one
    /// that no feature is near is near none either.
    pub fn contains(&self, other: &PlanBox) -> bool {
        (0..2).all(|k| self.lo[k] <= other.lo[k] && other.hi[k] <= self.hi[k])
    }

    /// Whether some point of the box is within `dist` of the plan point `p`.
    pub fn near_point(&self, p: Vec3, dist: f64) -> bool {
        let gap = |k: usize, v: f64| (self.lo[k] - v).max(v - self.hi[k]).max(0.0);
        let (gx, gy) = (gap(0, p.x), gap(1, p.y));
        gx * gx + gy * gy <= dist * dist
    }

    /// Whether some point of the box is within `dist` (each way, along x and y) of the plan
    /// segment from `a` to `b`: a point within `dist` of the segment is.
    pub fn near_segment(&self, a: Vec3, b: Vec3, dist: f64) -> bool {
        a.x.min(b.x) - dist <= self.hi[0]
            && a.x.max(b.x) + dist >= self.lo[0]
            && a.y.min(b.y) - dist <= self.hi[1]
            && a.y.max(b.y) + dist >= self.lo[1]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_box_holds_every_point_of_the_path() {
        let path = Path {
            c: Vec3::new(1.0, 0.5, 0.0),
            b: Vec3::new(2.0, -1.0, 0.0),
            a: Vec3::new(-1.5, 0.7, 0.0),
        };
        let b = PlanBox::of(&path, 2.0);
        for k in 0..=1000 {
            let p = path.at(2.0 * k as f64 / 1000.0);
            assert!(b.near_point(p, 0.0), "{p:?} outside {b:?}");
        }
        // The x turning point (t = 2/3, x = 5/3) is its right edge.
        assert!((b.hi[0] - 5.0 / 3.0).abs() < 1e-5);
        assert!(!b.near_point(Vec3::new(1.7, 0.5, 0.0), 0.01));
        assert!(b.near_point(Vec3::new(1.7, 0.5, 0.0), 0.04));
    }
}
