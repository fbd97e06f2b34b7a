//! How a shot fares when the cue cannot repeat it exactly: Monte Carlo over the execution
//! noise ([`crate::noise`]: independent normal errors in heading, elevation, speed and tip
//! offsets), each sample its own seeded generator, so the answer does not depend on the
//! thread count.

use crate::line::Line;
use crate::noise::{Noise, rng_for};
use crate::problem::Problem;
use rayon::prelude::*;
use snooker_engine::cue::Cue;

/// A shot's robustness to the execution noise.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Robustness {
    /// The noise (standard deviations).
    pub noise: Noise,
    /// Samples simulated.
    pub samples: usize,
    /// Share of the samples that pot the object ball in the pocket with no foul.
    pub pot_probability: f64,
    /// Mean of the cue ball's end position over the samples that simulated, m.
    pub cue_final_mean: [f64; 2],
    /// Root mean square distance of those ends from their mean, m.
    pub cue_final_spread: f64,
}

impl Problem {
    /// The robustness of strike `cue` aimed along `line`; `stream` tells shots apart in the
    /// noise's seeding.
    pub fn robustness(&self, cue: &Cue, line: &Line, stream: u64) -> Robustness {
        let noise = self.request.noise;
        let n = self.request.samples;
        let seed = self.request.seed;
        let ball = self.setup.balls[self.cue].state;
        let p = &self.setup.params;
        let runs: Vec<Option<(bool, [f64; 2])>> = (0..n as u64)
            .into_par_iter()
            .map(|k| {
                let c = noise.apply(cue, &ball, p, &mut rng_for(seed, &[stream, k]));
                self.trial(&c, line)
                    .map(|t| (t.pots(), [t.cue_final.x, t.cue_final.y]))
            })
            .collect();
        let pots = runs.iter().flatten().filter(|(p, _)| *p).count();
        let ends: Vec<[f64; 2]> = runs.iter().flatten().map(|(_, e)| *e).collect();
        let m = ends.len().max(1) as f64;
        let mean = [
            ends.iter().map(|e| e[0]).sum::<f64>() / m,
            ends.iter().map(|e| e[1]).sum::<f64>() / m,
        ];
        let spread = (ends
            .iter()
            .map(|e| (e[0] - mean[0]).powi(2) + (e[1] - mean[1]).powi(2))
            .sum::<f64>()
            / m)
            .sqrt();
        Robustness {
            noise,
            samples: n,
            pot_probability: pots as f64 / n as f64,
            cue_final_mean: mean,
            cue_final_spread: spread,
        }
    }
}
