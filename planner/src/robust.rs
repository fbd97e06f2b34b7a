//! How a shot fares when the cue cannot repeat it exactly: Monte Carlo over the execution
//! noise (independent normal errors in heading, speed and tip offsets), each sample its own
//! seeded generator, so the answer does not depend on the thread count.

use crate::problem::{Noise, Problem};
use rand::SeedableRng;
use rand::rngs::ChaCha8Rng;
use rand_distr::{Distribution, Normal};
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

/// One normal error of standard deviation `sd` (zero when `sd` is zero).
fn error(sd: f64, rng: &mut ChaCha8Rng) -> f64 {
    Normal::new(0.0, sd).map_or(0.0, |n| n.sample(rng))
}

impl Problem {
    /// The robustness of strike `cue`; `stream` tells shots apart in the noise's seeding.
    pub fn robustness(&self, cue: &Cue, stream: u64) -> Robustness {
        let noise = self.request.noise;
        let n = self.request.samples;
        let seed = self.request.seed ^ stream.wrapping_mul(0x9e37_79b9_7f4a_7c15);
        let runs: Vec<Option<(bool, [f64; 2])>> = (0..n as u64)
            .into_par_iter()
            .map(|k| {
                let mut rng =
                    ChaCha8Rng::seed_from_u64(seed ^ k.wrapping_mul(0xd1b5_4a32_d192_ed03));
                let c = Cue {
                    speed: cue.speed * (1.0 + error(noise.speed, &mut rng)),
                    aim: cue.aim + error(noise.aim, &mut rng),
                    offset: [
                        cue.offset[0] + error(noise.offset, &mut rng),
                        cue.offset[1] + error(noise.offset, &mut rng),
                    ],
                    elevation: cue.elevation,
                };
                // A strike the noise makes impossible (a miscue) pots nothing.
                self.trial(&c)
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
