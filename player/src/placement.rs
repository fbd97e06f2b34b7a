//! Where the cue ball in hand is placed (step 1 of docs/playing.md, "How a stroke is
//! chosen"): the D's grid scored by the position each point gives.

use crate::value::Valuer;
use snooker_rules::Frame;

/// Places for the cue ball in hand tried, and how far apart (m).
const PLACEMENTS: usize = 3;
const PLACEMENT_GAP: f64 = 0.08;

/// Places for the cue ball in hand: the best few of the D's grid (or its one clear place,
/// [`crate::value::in_hand_points`]) by the value of the pots
/// they leave, at least [`PLACEMENT_GAP`] apart.
pub(crate) fn placements(frame: &Frame, valuer: &Valuer) -> Vec<[f64; 2]> {
    let mut scored: Vec<(f64, [f64; 2])> = crate::value::in_hand_points(frame)
        .into_iter()
        .map(|p| (valuer.from(frame, p).0, [p.x, p.y]))
        .collect();
    // Best first; equal values keep the grid's order (its middle first).
    scored.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut out: Vec<[f64; 2]> = Vec::new();
    for (_, p) in scored {
        if out
            .iter()
            .all(|q| (p[0] - q[0]).hypot(p[1] - q[1]) >= PLACEMENT_GAP)
        {
            out.push(p);
        }
        if out.len() == PLACEMENTS {
            break;
        }
    }
    out
}
