//! Statistics of a chaotic shot (the break-off) and of an ensemble of nearly identical shots.
//!
//! Once a pack is struck, tiny differences (a solver's simultaneous treatment of touching balls,
//! a step of time) grow until individual outcomes have nothing in common; what two engines
//! that follow the same laws must share is the distribution of outcomes. Our engine is run on
//! an ensemble of the shot with the cue ball's heading turned by multiples of a tiny angle
//! (far below any player's precision, so each is "the same shot"), and rapier's outcome is
//! compared with the ensemble's mean and spread.

use crate::record::{Contact, Record};
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
pub fn stats(setup: &Setup, rec: &Record) -> Vec<Stat> {
    let count =
        |f: &dyn Fn(&Contact) -> bool| rec.impacts.iter().filter(|i| f(&i.contact)).count() as f64;
    let r = setup.params.ball_radius;
    let moved: Vec<Vec3> = setup
        .balls
        .iter()
        .zip(&rec.finals)
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
            value: count(&|c| matches!(c, Contact::Balls(..))),
        },
        Stat {
            name: "cushion impacts",
            value: count(&|c| matches!(c, Contact::Cushion(..))),
        },
        Stat {
            name: "pots",
            value: count(&|c| matches!(c, Contact::Pocket(..))),
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
