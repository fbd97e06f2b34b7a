//! The executed strikes' errors have the stated standard deviations: the strike played by
//! [`snooker_player::executed`] (the one `snooker play` simulates) minus the strike meant, over
//! 4,000 strokes of a fixed seed, for the standard noise and twice it, each component's sample
//! standard deviation within 5 % of the stated one (its standard error is 1.1 %: a 4.5-sigma
//! band) and its mean within 4.5 standard errors of zero; no noise plays the strike meant.

use snooker_engine::Cue;
use snooker_planner::{Noise, NoiseComponent};
use snooker_player::executed;

const N: u64 = 4000;

fn errors(noise: &Noise, seed: u64) -> Vec<[f64; 5]> {
    let frame = snooker_player::layouts::open_table_in_hand(3)
        .with_cue_ball_at([0.6, 0.9])
        .unwrap();
    // Well inside every limit: no error is clipped.
    let meant = Cue {
        speed: 2.0,
        aim: 0.4,
        offset: [0.002, -0.003],
        elevation: 0.035,
    };
    (1..=N)
        .map(|stroke| {
            let e = executed(&frame, &meant, noise, seed, stroke);
            [
                e.aim - meant.aim,
                e.elevation - meant.elevation,
                e.speed - meant.speed,
                e.offset[0] - meant.offset[0],
                e.offset[1] - meant.offset[1],
            ]
        })
        .collect()
}

#[test]
fn executed_strikes_err_with_the_stated_standard_deviations() {
    for scale in [1.0, 2.0] {
        let noise = Noise::STANDARD.scaled(scale);
        let e = errors(&noise, 2026);
        for (k, c) in NoiseComponent::ALL.into_iter().enumerate() {
            let sd = noise.get(c);
            let n = e.len() as f64;
            let mean = e.iter().map(|x| x[k]).sum::<f64>() / n;
            let var = e.iter().map(|x| (x[k] - mean).powi(2)).sum::<f64>() / (n - 1.0);
            let ratio = var.sqrt() / sd;
            assert!(
                (ratio - 1.0).abs() < 0.05,
                "{} x{scale}: sample sd {} against {sd} ({ratio})",
                c.name(),
                var.sqrt()
            );
            assert!(
                mean.abs() < 4.5 * sd / n.sqrt(),
                "{} x{scale}: mean {mean}",
                c.name()
            );
        }
    }
}

#[test]
fn the_components_are_independent() {
    let e = errors(&Noise::STANDARD, 7);
    let n = e.len() as f64;
    for a in 0..5 {
        for b in (a + 1)..5 {
            let (ma, mb) = (
                e.iter().map(|x| x[a]).sum::<f64>() / n,
                e.iter().map(|x| x[b]).sum::<f64>() / n,
            );
            let cov: f64 = e.iter().map(|x| (x[a] - ma) * (x[b] - mb)).sum::<f64>() / n;
            let sa = (e.iter().map(|x| (x[a] - ma).powi(2)).sum::<f64>() / n).sqrt();
            let sb = (e.iter().map(|x| (x[b] - mb).powi(2)).sum::<f64>() / n).sqrt();
            // The correlation of independent samples has standard error 1/sqrt(n) = 0.016.
            assert!((cov / (sa * sb)).abs() < 0.07, "components {a} and {b}");
        }
    }
}

#[test]
fn no_noise_plays_the_strike_meant() {
    for x in errors(&Noise::ZERO, 1).iter().take(50) {
        assert_eq!(*x, [0.0; 5]);
    }
}
