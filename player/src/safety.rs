//! Safeties (step 6 of docs/playing.md, "How a stroke is chosen"): when no pot is worth its
//! risk, the nearest balls on struck full, half and thin, valued by what they leave the
//! opponent.

use crate::agent::Context;
use crate::candidates::{self, ELEVATION};
use crate::decision::{Considered, PlanKind};
use crate::outcome::outcome;
use crate::player::{Evaluated, Place};
use crate::sampling::{MIN_CANDIDATES, MIN_SAMPLES, sample};
use crate::value::Valuer;
use rayon::prelude::*;
use snooker_engine::Cue;

/// Safety strokes: where the cue ball's path passes the ball aimed at (shares of 2R across
/// it: 0 full, ±0.9 thin), the cue speeds and heights (shares of the reach).
const SAFETY_CONTACTS: [f64; 7] = [-0.9, -0.6, -0.3, 0.0, 0.3, 0.6, 0.9];
const SAFETY_SPEEDS: [f64; 4] = [0.5, 0.9, 1.6, 2.8];
const SAFETY_HEIGHTS: [f64; 2] = [0.0, -0.5];
/// Balls on aimed at for safeties (the nearest).
const SAFETY_BALLS: usize = 6;

/// Safeties from `frame` (cue ball placed): the nearest balls on struck full, half and
/// thin at a few speeds, judged without noise; the best sampled under noise.
pub(crate) fn safeties(
    place: &Place,
    valuer: &Valuer,
    ctx: &Context,
    samples_budget: u64,
) -> (Vec<Evaluated>, u64) {
    let (frame, placement, place_index) = (place.frame, place.placement, place.index);
    let Some(cue) = frame.cue_index() else {
        return (Vec::new(), 0);
    };
    let balls = frame.balls();
    let r = frame.params().ball_radius;
    let c = balls[cue].state.pos;
    let mut on = frame.balls_on();
    on.sort_by(|&a, &b| {
        let d = |i: usize| (balls[i].state.pos - c).xy().norm();
        d(a).total_cmp(&d(b))
    });
    on.truncate(SAFETY_BALLS);
    let reach = candidates::bounds(frame).height.hi;
    let mut jobs = Vec::new();
    for &b in &on {
        let nominated = candidates::nomination(frame, balls[b].kind);
        let Ok(f) = frame.with_nomination(nominated) else {
            continue;
        };
        let to = balls[b].state.pos - c;
        let dist = to.xy().norm();
        for &across in &SAFETY_CONTACTS {
            let off = (across * 2.0 * r / dist).clamp(-1.0, 1.0).asin();
            let aim = to.y.atan2(to.x) + off;
            for &speed in &SAFETY_SPEEDS {
                for &h in &SAFETY_HEIGHTS {
                    let strike = Cue {
                        speed,
                        aim,
                        offset: [0.0, h * reach],
                        elevation: ELEVATION,
                    };
                    jobs.push((b, nominated, f.clone(), strike));
                }
            }
        }
    }
    let mut scored: Vec<(usize, f64, [f64; 2])> = jobs
        .par_iter()
        .enumerate()
        .filter_map(|(k, (_, _, f, strike))| {
            if ctx.watch.is_cancelled() {
                return None;
            }
            ctx.watch.count(1);
            let s = f.play(strike).ok()?;
            s.verdict.legal().then_some(())?;
            let o = outcome(f, &s.verdict, valuer, None);
            let cue_end = s.shot.final_states()[f.cue_index()?].pos;
            Some((k, o.value, [cue_end.x, cue_end.y]))
        })
        .collect();
    let mut used = jobs.len() as u64;
    scored.sort_by(|a, b| b.1.total_cmp(&a.1));
    let k = MIN_CANDIDATES.min(scored.len());
    let n = (samples_budget as usize)
        .checked_div(k)
        .map_or(0, |n| n.max(MIN_SAMPLES));
    let evaluated = scored
        .iter()
        .take(k)
        .enumerate()
        .map(|(i, &(j, _, cue_to))| {
            let (b, nominated, f, strike) = &jobs[j];
            let (value, _, sims) =
                sample(f, strike, valuer, None, ctx, [place_index, 1, i as u64], n);
            used += sims;
            Evaluated {
                placement,
                nominated: *nominated,
                strike: *strike,
                considered: Considered {
                    pot: String::new(),
                    ball: balls[*b].id.clone(),
                    pocket: String::new(),
                    kind: PlanKind::Safety,
                    via: Vec::new(),
                    pot_probability: 0.0,
                    cue_to,
                    value,
                    samples: n,
                },
            }
        })
        .collect();
    (evaluated, used)
}
