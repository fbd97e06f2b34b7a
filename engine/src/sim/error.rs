//! Why a shot could not be simulated.

use super::setup::SetupError;
use crate::impact::ImpactError;

/// Why a simulation stopped without finishing the shot.
#[derive(Clone, Debug, PartialEq)]
pub enum SimError {
    /// The setup, or the simulation's limits ([`super::SimOptions::validate`]), are invalid.
    Setup(SetupError),
    /// More than `max_events` events.
    TooManyEvents {
        /// The limit.
        limit: usize,
        /// Time reached, s.
        t: f64,
    },
    /// More than `max_events_at_instant` events without time advancing.
    Stuck {
        /// The instant, s.
        t: f64,
        /// Events at that instant.
        count: usize,
    },
    /// Balls still moving after `max_time`.
    DidNotStop {
        /// The limit, s.
        max_time: f64,
    },
    /// An impact model failed to converge (a bug: reported rather than passed on).
    Impact {
        /// Balls involved.
        balls: Vec<String>,
        /// Time, s.
        t: f64,
        /// What failed.
        error: ImpactError,
    },
    /// A non-finite number appeared (a bug: reported rather than passed on).
    NonFinite {
        /// Ball id.
        ball: String,
        /// Time, s.
        t: f64,
    },
}

impl std::fmt::Display for SimError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SimError::Setup(e) => write!(f, "{e}"),
            SimError::TooManyEvents { limit, t } => write!(
                f,
                "the shot exceeded {limit} events (at t = {t:.6} s); stopped as a runaway"
            ),
            SimError::Stuck { t, count } => write!(
                f,
                "{count} events at the same instant t = {t:.9} s without time advancing; stopped"
            ),
            SimError::DidNotStop { max_time } => write!(
                f,
                "balls were still moving after {max_time} s of simulated time \
                 (is there no rolling resistance or sliding friction?)"
            ),
            SimError::Impact { balls, t, error } => write!(
                f,
                "internal error: the impact of {} at t = {t} s failed: {}",
                balls.join(" and "),
                error.reason()
            ),
            SimError::NonFinite { ball, t } => write!(
                f,
                "internal error: a non-finite value appeared for ball {ball} at t = {t} s"
            ),
        }
    }
}

impl std::error::Error for SimError {}
