//! Statistics of a chaotic shot (the break-off) and of an ensemble of nearly identical shots.
//!
//! Once a pack is struck, tiny differences (a solver's simultaneous treatment of touching balls,
//! a step of time) grow until individual outcomes have nothing in common; what two engines
//! that follow the same laws must share is the distribution of outcomes. Our engine is run on
//! an ensemble of the shot with the cue ball's heading turned by multiples of a tiny angle
//! (far below any player's precision, so each is "the same shot"), and rapier's outcome is
//! compared with the ensemble's mean and spread.

use crate::digest::{Parties, ShotDigest};
use serde::Serialize;
use snooker_engine::{Setup, Vec3};

/// One outcome statistic of a shot.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Stat {
    /// Name.
    pub name: &'static str,
    /// Value.
    pub value: f64,
}

/// The statistics of a shot: ball-ball and cushion impacts, pots, balls moved by more than a
/// ball radius, and the RMS distance of the balls that moved from their mean final position.
pub fn stats(setup: &Setup, digest: &ShotDigest) -> Vec<Stat> {
    let count = |f: &dyn Fn(&Parties) -> bool| {
        digest.impacts.iter().filter(|i| f(&i.parties)).count() as f64
    };
    let r = setup.params.ball_radius;
    let moved: Vec<Vec3> = setup
        .balls
        .iter()
        .zip(&digest.finals)
        .filter(|(b, f)| f.pocket.is_none() && (f.pos.xy() - b.state.pos.xy()).norm() > r)
        .map(|(_, f)| Vec3::new(f.pos.x, f.pos.y, 0.0))
        .collect();
    let spread = if moved.is_empty() {
        0.0
    } else {
        let mean = moved.iter().sum::<Vec3>() / moved.len() as f64;
        (moved.iter().map(|p| (p - mean).norm_squared()).sum::<f64>() / moved.len() as f64).sqrt()
    };
    vec![
        Stat {
            name: "ball-ball impacts",
            value: count(&|c| matches!(c, Parties::Balls(..))),
        },
        Stat {
            name: "cushion impacts",
            value: count(&|c| c.is_cushion()),
        },
        Stat {
            name: "pots",
            value: count(&|c| matches!(c, Parties::Pocket(..))),
        },
        Stat {
            name: "balls moved",
            value: moved.len() as f64,
        },
        Stat {
            name: "spread of the moved balls (m)",
            value: spread,
        },
    ]
}

/// Angle by which the cue ball's heading is turned between members of the ensemble, rad
/// (0.0057 degrees: far below a player's aim).
pub const HEADING_STEP: f64 = 1e-4;

/// Members of the ensemble on each side of the shot as given.
pub const HALF_WIDTH: i32 = 8;

/// The shot with the first moving ball's velocity turned by `angle` about the vertical.
pub fn turned(setup: &Setup, angle: f64) -> Setup {
    let mut s = setup.clone();
    if let Some(b) = s.balls.iter_mut().find(|b| b.state.vel.xy().norm() > 0.0) {
        let v = b.state.vel;
        let (sin, cos) = angle.sin_cos();
        b.state.vel = Vec3::new(v.x * cos - v.y * sin, v.x * sin + v.y * cos, v.z);
    }
    s
}

/// One statistic of rapier's shot against our engine's ensemble.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StatRow {
    /// Name.
    pub name: &'static str,
    /// Mean over our ensemble.
    pub ours_mean: f64,
    /// Standard deviation over our ensemble.
    pub ours_sd: f64,
    /// Smallest value in our ensemble.
    pub ours_min: f64,
    /// Largest value in our ensemble.
    pub ours_max: f64,
    /// rapier's value for the shot as given.
    pub rapier: f64,
}

/// Summarises our ensemble's statistics (one list per member) against rapier's.
pub fn summarise(ours: &[Vec<Stat>], rapier: &[Stat]) -> Vec<StatRow> {
    rapier
        .iter()
        .enumerate()
        .map(|(k, r)| {
            let xs: Vec<f64> = ours.iter().map(|m| m[k].value).collect();
            let n = xs.len().max(1) as f64;
            let mean = xs.iter().sum::<f64>() / n;
            let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
            StatRow {
                name: r.name,
                ours_mean: mean,
                ours_sd: var.sqrt(),
                ours_min: xs.iter().copied().fold(f64::INFINITY, f64::min),
                ours_max: xs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
                rapier: r.value,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn summary_of_a_constant_ensemble() {
        let m = vec![Stat {
            name: "x",
            value: 2.0,
        }];
        let rows = summarise(
            &[m.clone(), m.clone()],
            &[Stat {
                name: "x",
                value: 3.0,
            }],
        );
        assert_eq!(rows[0].ours_mean, 2.0);
        assert_eq!(rows[0].ours_sd, 0.0);
        assert_eq!(rows[0].rapier, 3.0);
    }
}
