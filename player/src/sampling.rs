//! Monte Carlo over the execution noise (step 5 of docs/playing.md, "How a stroke is
//! chosen"): a strike played many times with the noise drawn, each outcome judged by the
//! rules and valued ([`crate::outcome`]); every draw seeded from (seed, stroke, the
//! candidate's coordinates, sample), so the mean is the same on any thread count.

use crate::agent::Context;
use crate::outcome::outcome;
use crate::value::Valuer;
use rayon::prelude::*;
use snooker_engine::Cue;
use snooker_planner::rng_for;
use snooker_rules::Frame;

/// Fewest and most candidates sampled under noise.
pub(crate) const MIN_CANDIDATES: usize = 4;
pub(crate) const MAX_CANDIDATES: usize = 20;
/// Fewest and most noise samples per candidate.
pub(crate) const MIN_SAMPLES: usize = 8;
pub(crate) const MAX_SAMPLES: usize = 96;

/// How many candidates of `available` to sample and how many times each, within
/// `samples_budget` shots.
pub(crate) fn allotment(samples_budget: u64, available: usize) -> (usize, usize) {
    let k = ((samples_budget / (MIN_SAMPLES as u64 * 6)) as usize)
        .clamp(MIN_CANDIDATES, MAX_CANDIDATES)
        .min(available);
    let n = (samples_budget as usize)
        .checked_div(k)
        .map_or(0, |n| n.clamp(MIN_SAMPLES, MAX_SAMPLES));
    (k, n)
}

/// Plays `strike` from `frame` under `ctx`'s noise `n` times (draws seeded from the
/// coordinates `coords` and the sample's number) and returns (mean value, pot share).
pub(crate) fn sample(
    frame: &Frame,
    strike: &Cue,
    valuer: &Valuer,
    pot: Option<&str>,
    ctx: &Context,
    coords: [u64; 3],
    n: usize,
) -> (f64, f64, u64) {
    let Some(cue) = frame.cue_index() else {
        return (f64::NEG_INFINITY, 0.0, 0);
    };
    let ball = frame.balls()[cue].state;
    let p = frame.params();
    let results: Vec<Option<(f64, bool)>> = (0..n as u64)
        .into_par_iter()
        .map(|k| {
            if ctx.watch.is_cancelled() {
                return None;
            }
            let mut rng = rng_for(ctx.seed, &[ctx.stroke, coords[0], coords[1], coords[2], k]);
            let executed = ctx.noise.apply(strike, &ball, p, &mut rng);
            ctx.watch.count(1);
            let stroke = frame.play(&executed).ok()?;
            let o = outcome(frame, &stroke.verdict, valuer, pot);
            Some((o.value, o.potted))
        })
        .collect();
    // A sample the engine could not simulate counts as the worst: a foul's and the
    // opponent in hand (it does not happen on a valid frame: the engine always simulates).
    let worst = -(7.0 + valuer.future(frame, 0.0));
    let total: f64 = results.iter().map(|r| r.map_or(worst, |x| x.0)).sum();
    let pots = results.iter().filter(|r| r.is_some_and(|x| x.1)).count();
    (total / n as f64, pots as f64 / n as f64, n as u64)
}
