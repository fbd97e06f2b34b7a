//! Pocket capture: a ball on the cloth drops once its centre enters the fall circle (plan).
//!
//! A ball in the air over a pocket's opening (the pocket geometry is docs/physics.md's Table
//! section: the fall circle behind the mouth, its front touching the line joining the jaw
//! points) drops in, or flies over it:
//! - its lowest point below the nose's height when its centre enters the fall: it is below the
//!   pocket's surround, over the hole, and drops in — at once, or after striking the fall's far
//!   edge (the pocket's back) or a facing below the nose: either way it is pocketed there;
//! - higher, it drops in when its lowest point comes down to the nose's height with its
//!   centre still over the fall;
//! - if its centre reaches the far half of the fall's edge (beyond the diameter across the
//!   pocket's axis) first, still higher than the nose, it clears the pocket's back and leaves
//!   the table (a ball "forced off the table", WPBSA rules §3, as over a cushion's nose).
//!
//! Its other ways out of a pocket's opening are the cushion's: the jaws' and facings' edges
//! ([`super::cushion`]).
//!
//! The pocket's back: past the fall's diameter across the pocket's axis there is no bed (the
//! hole, then the pocket's back). A ball whose centre reaches that line beside the fall, which
//! only a pocket widened or deepened beyond a real one's allows (a `[table]` with a wide mouth
//! and a deep fall: its facings no longer close on the fall), strikes the back and drops in
//! ([`back_time`]), or, in the air with its lowest point above the nose, clears it and leaves
//! the table. Before, such a ball rolled on past the facings' ends, on a cloth that is not
//! there, and came to rest metres outside the table.

use super::cushion::NoseEdge;
use super::roots::{entries, exits, first_entry, line_contacts};
use crate::motion::Path;
use crate::table::Pocket;
use polycool::Quadratic;

/// First time in [0, window] at which `path`'s centre enters the fall of `pocket`.
pub fn capture_time(path: &Path, pocket: &Pocket, window: f64) -> Option<f64> {
    let mut rel = path.plan();
    rel.c -= pocket.centre;
    first_entry(&rel, pocket.radius, window)
}

/// First time in [0, window] at which a ball in the air on `path` drops into `pocket` (see
/// the module docs): its centre entering the fall with its lowest point below the nose, or
/// its lowest point coming down to the nose's height with its centre over the fall (or both
/// now).
pub fn drop_time_in_air(path: &Path, pocket: &Pocket, edge: NoseEdge, window: f64) -> Option<f64> {
    let mut rel = path.plan();
    rel.c -= pocket.centre;
    let over = |t: f64| rel.at(t).norm() <= pocket.radius;
    if over(0.0) && !edge.cleared_at(path.c.z) {
        return Some(0.0);
    }
    let low_entry = entries(&rel, pocket.radius, window).find(|&t| !edge.cleared_at(path.at(t).z));
    // z(t) = h + R, coming down.
    let comes_down = Quadratic::new([path.c.z - edge.radius - edge.height, path.b.z, path.a.z])
        .roots()
        .into_iter()
        .filter(|&t| (0.0..=window).contains(&t) && path.velocity(t).z < 0.0)
        .find(|&t| over(t));
    match (low_entry, comes_down) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// First time in [0, window] at which a ball in the air on `path` reaches the far half of the
/// edge of `pocket`'s fall (moving out of it), and whether it then clears the pocket's back
/// (its lowest point above the nose: it leaves the table) or not (it strikes the fall's far
/// edge and drops in).
pub fn far_edge_time(
    path: &Path,
    pocket: &Pocket,
    edge: NoseEdge,
    window: f64,
) -> Option<(f64, bool)> {
    let mut rel = path.plan();
    rel.c -= pocket.centre;
    let axis = pocket.axis();
    exits(&rel, pocket.radius, window)
        .find(|&t| rel.at(t).dot(&axis) >= 0.0)
        .map(|t| (t, edge.cleared_at(path.at(t).z)))
}

/// First time in [0, window] at which `path`'s centre crosses the line of `pocket`'s back
/// (the fall's diameter across the pocket's axis), moving out, beside the fall and within
/// [`Pocket::back_reach`] of the mouth: the pocket's back (module docs). A
/// centre that reaches the line over the fall is the fall's ([`capture_time`],
/// [`far_edge_time`]).
pub fn back_time(path: &Path, pocket: &Pocket, window: f64) -> Option<f64> {
    let reach = pocket.back_reach();
    let plan = path.plan();
    line_contacts(&plan, pocket.centre, -pocket.axis(), 0.0, window)
        .find(|(_, at)| {
            (at - pocket.centre).xy().norm() > pocket.radius
                && (at - pocket.mouth).xy().norm() <= reach
        })
        .map(|(t, _)| t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Vec3;
    use crate::params::Params;
    use crate::table::{SnookerDims, Table};

    fn fly(from: Vec3, vel: Vec3, g: f64) -> Path {
        Path {
            c: from,
            b: vel,
            a: Vec3::new(0.0, 0.0, -0.5 * g),
        }
    }

    #[test]
    fn a_ball_in_the_air_drops_in_or_flies_over() {
        let p = Params::default();
        let table = Table::snooker(&SnookerDims::default());
        let pk = table
            .pockets
            .iter()
            .find(|k| k.name == "middle-right")
            .unwrap();
        let edge = NoseEdge {
            height: p.cushion_height,
            radius: p.ball_radius,
        };
        let r = p.ball_radius;
        // Straight down the pocket's axis (-y), just off the cloth: drops in as it enters.
        let low = fly(
            pk.mouth + Vec3::new(0.0, 0.1, r + 0.001),
            Vec3::new(0.0, -1.0, 0.1),
            p.g,
        );
        let t = drop_time_in_air(&low, pk, edge, 1.0).unwrap();
        assert!((low.at(t) - pk.centre).xy().norm() - pk.radius < 1e-9);
        // High and fast: crosses the whole fall and clears its back.
        let high = fly(
            pk.mouth + Vec3::new(0.0, 0.1, 0.2),
            Vec3::new(0.0, -5.0, 0.0),
            p.g,
        );
        assert_eq!(drop_time_in_air(&high, pk, edge, 0.1), None);
        let (t, clear) = far_edge_time(&high, pk, edge, 0.1).unwrap();
        assert!(clear);
        assert!((high.at(t).y - (pk.centre.y - pk.radius)).abs() < 1e-9);
        // High and slow: comes down over the fall and drops in before the far edge.
        let slow = fly(
            pk.mouth + Vec3::new(0.0, 0.02, 0.12),
            Vec3::new(0.0, -0.3, 0.0),
            p.g,
        );
        let t = drop_time_in_air(&slow, pk, edge, 1.0).unwrap();
        assert!((slow.at(t).z - r - p.cushion_height).abs() < 1e-9);
        assert!(far_edge_time(&slow, pk, edge, 1.0).is_none_or(|(te, _)| te > t));
    }
}
