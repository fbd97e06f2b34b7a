//! Why the workflow, a fit or a synthetic measurement could not be made.

use crate::catalogue::Effect;
use crate::data::DataError;
use snooker_engine::shown::Shown;
use snooker_engine::{CueError, SimError};

/// Why the discrepancy workflow (or one of its fits or films) stopped.
#[derive(Clone, Debug, PartialEq)]
pub enum DiscrepancyError {
    /// The measurement is not usable.
    Data(DataError),
    /// A shot's strike cannot be played with the values tried.
    Strike {
        /// The shot.
        shot: String,
        /// Why.
        error: CueError,
    },
    /// A shot could not be simulated with the values tried.
    Simulation {
        /// The shot.
        shot: String,
        /// Why.
        error: SimError,
    },
    /// An effect was given a wrong number of values.
    EffectValues {
        /// The effect.
        effect: Effect,
        /// Values given.
        given: usize,
        /// Its parameters.
        expected: usize,
    },
    /// Fewer residuals than unknowns.
    TooFewResiduals {
        /// Residuals.
        residuals: usize,
        /// Unknowns.
        unknowns: usize,
    },
    /// The least-squares solver failed: MPFIT's words (its error type can be neither cloned
    /// nor compared, as this one is).
    Solver(String),
    /// The effect has no admissible value in this model (a tilt without rolling resistance).
    NotApplicable,
    /// A camera setting is out of range.
    Camera {
        /// The setting.
        setting: &'static str,
        /// Its admissible range, for people.
        range: &'static str,
        /// The value given.
        value: f64,
    },
}

impl std::fmt::Display for DiscrepancyError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            DiscrepancyError::Data(e) => write!(f, "{e}"),
            DiscrepancyError::Strike { shot, error } => write!(f, "shot {shot}: strike: {error}"),
            DiscrepancyError::Simulation { shot, error } => write!(f, "shot {shot}: {error}"),
            DiscrepancyError::EffectValues {
                effect,
                given,
                expected,
            } => write!(
                f,
                "{}: {given} values for {expected} parameters",
                effect.id()
            ),
            DiscrepancyError::TooFewResiduals {
                residuals,
                unknowns,
            } => write!(f, "{residuals} residuals cannot fit {unknowns} unknowns"),
            DiscrepancyError::Solver(e) => write!(f, "the fit failed: {e}"),
            DiscrepancyError::NotApplicable => {
                write!(f, "not applicable: no admissible value in this model")
            }
            DiscrepancyError::Camera {
                setting,
                range,
                value,
            } => write!(f, "{setting} must be {range}, got {}", Shown(*value)),
        }
    }
}

impl std::error::Error for DiscrepancyError {}

impl From<DataError> for DiscrepancyError {
    fn from(e: DataError) -> Self {
        DiscrepancyError::Data(e)
    }
}
