//! Spotting colours (WPBSA Section 3 Rule 7; formats.md, "Referee result"): a colour goes back
//! to its own spot; if that is occupied, to the highest-value spot free; if every spot is
//! occupied, to the point nearest its own spot on the line from it towards the top cushion at
//! which it touches no ball (touching allowed); the pink and the black, if there is no room
//! there, to the nearest such point below the spot on the centre line. Several colours: the
//! highest value first, each placed before the next is judged. A spot is occupied when a
//! ball's centre is closer than 2R to it (Section 2 Rule 18, with the real ball radius).

use crate::colour::Colour;
use snooker_engine::{Params, SnookerDims, Vec3};

/// A colour put back on the table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Respot {
    /// The colour.
    pub colour: Colour,
    /// Where its centre goes (plan, z = 0).
    pub pos: Vec3,
}

/// The spot of a colour.
pub fn spot(dims: &SnookerDims, colour: Colour) -> Vec3 {
    dims.spots()
        .into_iter()
        .find(|s| s.name == colour.name())
        .map_or(Vec3::zeros(), |s| s.pos)
}

/// True when a ball's centre among `balls` is closer than 2R to `p` (plan).
pub fn occupied(p: Vec3, balls: &[Vec3], radius: f64) -> bool {
    let lim = (2.0 * radius).powi(2);
    balls.iter().any(|b| {
        let (dx, dy) = (b.x - p.x, b.y - p.y);
        dx * dx + dy * dy < lim
    })
}

/// The smallest s in [0, `s_max`] at which a ball centred at `origin + s dir` is 2R or more
/// from every ball of `balls` (plan), if any.
fn first_clear(origin: Vec3, dir: Vec3, s_max: f64, balls: &[Vec3], radius: f64) -> Option<f64> {
    let four_r2 = (2.0 * radius).powi(2);
    // Each ball blocks the open interval (s_b - w, s_b + w) of the line.
    let blocks: Vec<(f64, f64)> = balls
        .iter()
        .filter_map(|b| {
            let rel = Vec3::new(b.x - origin.x, b.y - origin.y, 0.0);
            let s = rel.dot(&dir);
            let h2 = rel.norm_squared() - s * s;
            (h2 < four_r2).then(|| (s, (four_r2 - h2).sqrt()))
        })
        .collect();
    let mut candidates: Vec<f64> = std::iter::once(0.0)
        .chain(blocks.iter().map(|&(s, w)| s + w))
        .filter(|&c| (0.0..=s_max).contains(&c))
        .collect();
    candidates.sort_by(f64::total_cmp);
    candidates.into_iter().find(|&c| {
        blocks
            .iter()
            .all(|&(s, w)| (c - s).abs() >= w * (1.0 - 1e-12))
    })
}

/// Where `colour` goes with `balls` (plan centres) on the table, or `None` if nowhere on its
/// lines (never on a full-size table: 21 balls block at most 2.2 m of a line over 3 m long).
pub fn place(colour: Colour, balls: &[Vec3], dims: &SnookerDims, params: &Params) -> Option<Vec3> {
    let r = params.ball_radius;
    let own = spot(dims, colour);
    if !occupied(own, balls, r) {
        return Some(own);
    }
    for c in Colour::ALL.into_iter().rev() {
        let p = spot(dims, c);
        if !occupied(p, balls, r) {
            return Some(p);
        }
    }
    // Every spot occupied: towards the top cushion, then (the pink and the black by the rules;
    // the others only here, where the rules are silent and it never happens) below the spot.
    let contact = params.cushion_contact_distance();
    let up = Vec3::new(1.0, 0.0, 0.0);
    if let Some(s) = first_clear(own, up, dims.length - contact - own.x, balls, r) {
        return Some(own + s * up);
    }
    first_clear(own, -up, own.x - contact, balls, r).map(|s| own - s * up)
}

/// Places `colours` back on the table with `balls` (plan centres) on it: the highest value
/// first, each clear of the balls and of the colours placed before it. `Err` names a colour
/// that found no room.
pub fn respot(
    colours: &[Colour],
    balls: &[Vec3],
    dims: &SnookerDims,
    params: &Params,
) -> Result<Vec<Respot>, Colour> {
    let mut order = colours.to_vec();
    order.sort_by(|a, b| b.cmp(a));
    let mut on_table = balls.to_vec();
    let mut out = Vec::with_capacity(order.len());
    for colour in order {
        let pos = place(colour, &on_table, dims, params).ok_or(colour)?;
        on_table.push(pos);
        out.push(Respot { colour, pos });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn setup() -> (SnookerDims, Params) {
        (SnookerDims::default(), Params::default())
    }

    #[test]
    fn occupied_is_closer_than_2r_with_touching_free() {
        let (d, p) = setup();
        let r = p.ball_radius;
        let black = spot(&d, Colour::Black);
        assert!(occupied(
            black,
            &[black + Vec3::new(2.0 * r - 1e-6, 0.0, 0.0)],
            r
        ));
        assert!(!occupied(black, &[black + Vec3::new(2.0 * r, 0.0, 0.0)], r));
    }

    #[test]
    fn the_line_search_stops_where_the_ball_touches() {
        let (d, p) = setup();
        let r = p.ball_radius;
        let spots: Vec<Vec3> = d.spots().iter().map(|s| s.pos).collect();
        // Every spot taken, and a ball just up the table from the pink's spot.
        let pink = spot(&d, Colour::Pink);
        let mut balls = spots.clone();
        balls.push(pink + Vec3::new(2.0 * r, 0.0, 0.0));
        let at = place(Colour::Pink, &balls, &d, &p).unwrap();
        assert!((at.y - pink.y).abs() < 1e-15);
        // Touches the ball at 2R from the spot: 4R up the table.
        assert!((at.x - (pink.x + 4.0 * r)).abs() < 1e-12, "{at:?}");
        assert!(
            balls
                .iter()
                .all(|b| (b - at).norm() >= 2.0 * r * (1.0 - 1e-12))
        );
    }
}
