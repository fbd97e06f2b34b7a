//! Snookered (WPBSA Section 2 Rule 17; Section 3 Rule 12 "Snookered after a Foul"): the cue
//! ball is snookered when it cannot hit both extreme edges of any ball on in straight lines,
//! only balls not on obstructing (cushions do not). With the cue ball in hand, only if that
//! holds from every position in the D (Section 2 Rule 17). The effective snookering ball, the
//! nearest in the way (none when reds are obstructed by different balls), decides whether a
//! free ball snookers (Section 2 Rule 17(b), (c); Section 3 Rule 12).
//!
//! Geometry: to hit an extreme edge of a ball on at O, the cue ball's centre runs from C along
//! a tangent to the circle of radius 2R about O, to the tangent point T where it grazes the
//! ball. That edge can be hit when no ball not on comes within 2R of the segment C-T (the cue
//! ball sweeps a band 2R wide around it). A cue ball touching a ball on can play it.
//!
//! A cushion's curved face, a pocket's jaw, nearer the cue ball on such a path than the
//! first ball not on in it, leaves that edge not snookered (Section 2 Rule 17(e): "If the
//! curved face of a cushion obstructs the cue-ball and is closer to the cue-ball than any
//! obstructing ball not on, the cue-ball is not snookered"): a cue ball left in the jaws
//! after a foul gives no free ball for a ball behind the jaw.

use crate::in_hand::TheD;
use snooker_engine::{Params, Table, Vec3};

/// Clearance below which a ball obstructs, relative to 2R: exact touching does not obstruct.
const TOUCH: f64 = 1e-12;

/// A cushion's curved face (a pocket's jaw) as the cue ball's centre meets it (plan): it
/// cannot come nearer than `reach` to `centre`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Curved {
    /// The arc's centre (plan).
    pub centre: Vec3,
    /// The arc's radius plus R cos(theta), the nose height's contact distance, m.
    pub reach: f64,
}

/// The curved faces of `table`'s cushions: its jaws, as whole circles (the rest of each arc's
/// circle lies behind the cushion, where no path on the cloth goes).
pub fn curved_faces(table: &Table, params: &Params) -> Vec<Curved> {
    let d = params.cushion_contact_distance();
    table
        .jaws
        .iter()
        .map(|j| Curved {
            centre: Vec3::new(j.centre.x, j.centre.y, 0.0),
            reach: j.radius + d,
        })
        .collect()
}

/// How far the cue ball's centre runs from `a` towards `b` before it comes `reach` from `q`
/// (plan), if it does on the segment.
fn first_contact(a: Vec3, b: Vec3, q: Vec3, reach: f64) -> Option<f64> {
    let (a, q) = (Vec3::new(a.x, a.y, 0.0), Vec3::new(q.x, q.y, 0.0));
    let b = Vec3::new(b.x, b.y, 0.0);
    if segment_distance2(q, a, b) >= reach * reach {
        return None;
    }
    let u = (b - a).normalize();
    let w = q - a;
    let along = w.dot(&u);
    let h2 = w.norm_squared() - along * along;
    Some((along - (reach * reach - h2).max(0.0).sqrt()).max(0.0))
}

/// Squared distance from `p` to the segment `a`-`b` (plan).
fn segment_distance2(p: Vec3, a: Vec3, b: Vec3) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
    (a + t * ab - p).norm_squared()
}

/// The two tangent points: where the cue ball's centre is when it grazes the ball at `target`
/// on one extreme edge or the other, coming straight from `cue`; `None` when they touch.
pub fn edge_contacts(cue: Vec3, target: Vec3, radius: f64) -> Option<[Vec3; 2]> {
    let cue = Vec3::new(cue.x, cue.y, 0.0);
    let d = Vec3::new(target.x, target.y, 0.0) - cue;
    let dist = d.norm();
    let two_r = 2.0 * radius;
    if dist <= two_r {
        return None;
    }
    let u = d / dist;
    let n = Vec3::new(-u.y, u.x, 0.0);
    let (sin, cos) = (two_r / dist, (1.0 - (two_r / dist).powi(2)).sqrt());
    let along = dist * cos;
    Some([1.0, -1.0].map(|side| cue + along * (cos * u + side * sin * n)))
}

/// The indices of `obstacles` (centres) in the way of one extreme edge or the other of the ball
/// at `target`, struck straight from `cue`.
fn obstructing(cue: Vec3, target: Vec3, obstacles: &[Vec3], radius: f64) -> Vec<usize> {
    let Some(contacts) = edge_contacts(cue, target, radius) else {
        return Vec::new();
    };
    let cue = Vec3::new(cue.x, cue.y, 0.0);
    let limit = (2.0 * radius * (1.0 - TOUCH)).powi(2);
    (0..obstacles.len())
        .filter(|&k| {
            let o = Vec3::new(obstacles[k].x, obstacles[k].y, 0.0);
            contacts
                .iter()
                .any(|&t| segment_distance2(o, cue, t) < limit)
        })
        .collect()
}

/// True when the cue ball at `cue` can hit both extreme edges of the ball at `target` in
/// straight lines, none of `obstacles` (centres) in the way.
pub fn both_edges_clear(cue: Vec3, target: Vec3, obstacles: &[Vec3], radius: f64) -> bool {
    obstructing(cue, target, obstacles, radius).is_empty()
}

/// The effective snookering balls (WPBSA Section 2 Rule 17(b), (c)), as indices of `not_on`:
/// of the balls obstructing a ball on, the nearest to the cue ball (all of them when
/// equidistant); when the balls on (reds) are obstructed by different nearest balls, none.
/// Empty when the cue ball is not snookered ([`is_snookered`], with `curved`).
pub fn effective_snookering(
    cue: Vec3,
    on: &[Vec3],
    not_on: &[Vec3],
    curved: &[Curved],
    radius: f64,
) -> Vec<usize> {
    if on.is_empty() || !is_snookered(cue, on, not_on, curved, radius) {
        return Vec::new();
    }
    let dist = |k: usize| {
        let (dx, dy) = (not_on[k].x - cue.x, not_on[k].y - cue.y);
        dx.hypot(dy)
    };
    let nearest = |target: Vec3| -> Vec<usize> {
        let by = obstructing(cue, target, not_on, radius);
        let least = by.iter().map(|&k| dist(k)).fold(f64::INFINITY, f64::min);
        by.into_iter().filter(|&k| dist(k) <= least).collect()
    };
    let mut common = nearest(on[0]);
    for &o in &on[1..] {
        let here = nearest(o);
        common.retain(|k| here.contains(k));
    }
    common
}

/// True when the cue ball at `cue` can hit both extreme edges of the ball at `target` as the
/// rules count it: no ball of `not_on` in the way of either, or a curved face of `curved`
/// met before the first such ball (Rule 17(e)).
fn both_edges_open(cue: Vec3, target: Vec3, not_on: &[Vec3], curved: &[Curved], r: f64) -> bool {
    let Some(contacts) = edge_contacts(cue, target, r) else {
        return true;
    };
    let ball_reach = 2.0 * r * (1.0 - TOUCH);
    contacts.iter().all(|&t| {
        let ball = not_on
            .iter()
            .filter_map(|&q| first_contact(cue, t, q, ball_reach))
            .fold(f64::INFINITY, f64::min);
        let face = curved
            .iter()
            .filter_map(|c| first_contact(cue, t, c.centre, c.reach))
            .fold(f64::INFINITY, f64::min);
        ball == f64::INFINITY || face < ball
    })
}

/// True when the cue ball at `cue` is snookered: no ball of `on` can be hit on both extreme
/// edges, with the balls `not_on` obstructing and the curved faces `curved` nearer than they
/// leaving an edge open (Rule 17(e); [`curved_faces`]). With nothing on, nothing can be hit:
/// snookered.
pub fn is_snookered(
    cue: Vec3,
    on: &[Vec3],
    not_on: &[Vec3],
    curved: &[Curved],
    radius: f64,
) -> bool {
    !on.iter()
        .any(|&o| both_edges_open(cue, o, not_on, curved, radius))
}

/// Spacing of the positions of the D tried for a cue ball in hand, m.
pub const IN_HAND_STEP: f64 = 0.005;

/// True when the cue ball in hand is snookered from every position in the D, sampled on a
/// grid [`IN_HAND_STEP`] apart (positions touching a ball are not places it could be played
/// from and are skipped). Stops at the first position that is not snookered.
pub fn is_snookered_in_hand(
    d: &TheD,
    on: &[Vec3],
    not_on: &[Vec3],
    curved: &[Curved],
    radius: f64,
) -> bool {
    let two_r2 = (2.0 * radius).powi(2);
    d.grid(IN_HAND_STEP).all(|p| {
        let blocked = on.iter().chain(not_on).any(|b| {
            let (dx, dy) = (b.x - p.x, b.y - p.y);
            dx * dx + dy * dy <= two_r2
        });
        blocked || is_snookered(p, on, not_on, curved, radius)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const R: f64 = 0.02625;

    fn v(x: f64, y: f64) -> Vec3 {
        Vec3::new(x, y, R)
    }

    #[test]
    fn the_tangent_points_graze_the_ball_at_2r() {
        let [a, b] = edge_contacts(v(0.5, 0.5), v(1.5, 0.7), R).unwrap();
        for t in [a, b] {
            assert!(((t - Vec3::new(1.5, 0.7, 0.0)).norm() - 2.0 * R).abs() < 1e-12);
            // Tangent: the path is perpendicular to the radius at T.
            let path = t - Vec3::new(0.5, 0.5, 0.0);
            assert!(path.dot(&(t - Vec3::new(1.5, 0.7, 0.0))).abs() < 1e-12);
        }
        assert!(edge_contacts(v(0.5, 0.5), v(0.5 + 2.0 * R, 0.5), R).is_none());
    }

    #[test]
    fn a_ball_in_the_line_snookers_one_to_the_side_half_snookers() {
        let (cue, red) = (v(1.0, 0.9), v(2.0, 0.9));
        assert!(!is_snookered(cue, &[red], &[], &[], R));
        // Full in the line.
        assert!(is_snookered(cue, &[red], &[v(1.5, 0.9)], &[], R));
        // Off the line by 2.5R, midway: the nearer edge's path runs about R off the centre
        // line there, and the cue ball's band 2R about it reaches the obstacle.
        assert!(is_snookered(cue, &[red], &[v(1.5, 0.9 + 2.5 * R)], &[], R));
        // Off by 4.5R: both edges clear.
        assert!(!is_snookered(cue, &[red], &[v(1.5, 0.9 + 4.5 * R)], &[], R));
        // Balls on never obstruct; a second red in the open does.
        assert!(!is_snookered(cue, &[red, v(1.5, 0.9)], &[], &[], R));
        assert!(!is_snookered(
            cue,
            &[red, v(1.0, 0.3)],
            &[v(1.5, 0.9)],
            &[],
            R
        ));
    }

    #[test]
    fn the_nearest_obstructing_ball_is_the_effective_snookering_ball() {
        let (cue, red) = (v(1.0, 0.9), v(2.0, 0.9));
        // Two balls in the line: the nearer snookers (Section 2 Rule 17(b)).
        let balls = [v(1.7, 0.9), v(1.3, 0.9)];
        assert_eq!(effective_snookering(cue, &[red], &balls, &[], R), [1]);
        // Not snookered: none.
        assert!(effective_snookering(cue, &[red], &[v(1.5, 1.2)], &[], R).is_empty());
        // Two reds each behind its own ball: none (Rule 17(c)); behind the same one: that one.
        let reds = [red, v(2.0, 1.4)];
        let blockers = [v(1.5, 0.9), v(1.5, 1.15)];
        assert!(effective_snookering(cue, &reds, &blockers, &[], R).is_empty());
        let close = [v(1.1, 0.95)];
        let near_reds = [v(2.0, 0.95), v(2.0, 1.0)];
        assert_eq!(effective_snookering(cue, &near_reds, &close, &[], R), [0]);
    }
}
