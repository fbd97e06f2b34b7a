//! Parameter overrides: a scene's or a model file's `[params]`, and `--param NAME=VALUE` on the
//! command line. Names, ranges and sources are the engine's one declaration
//! ([`snooker_engine::params::PARAMS`]).

use crate::file::ParamOverrides;
use snooker_engine::Params;
use snooker_engine::params::{NOSE_HEIGHT_PER_RADIUS, PARAMS, ParamError};

impl ParamOverrides {
    /// `base` overridden by the values given. The nose height follows a new ball radius unless
    /// given too (h = 7R/5, thesis §6.2).
    pub fn apply_to(&self, base: Params) -> Params {
        let mut p = base;
        if let Some(&(_, r)) = self.0.iter().find(|(n, _)| *n == "ball_radius")
            && !self.has("cushion_height")
        {
            p.cushion_height = NOSE_HEIGHT_PER_RADIUS * r;
        }
        for &(name, v) in &self.0 {
            if let Some(slot) = p.field_mut(name) {
                *slot = v;
            }
        }
        p
    }
}

/// A `--param NAME=VALUE` that cannot be used.
#[derive(Clone, Debug, PartialEq)]
pub enum OverrideError {
    /// Not of the form NAME=VALUE.
    Syntax(String),
    /// The value is not a number.
    NotANumber {
        /// The whole override.
        given: String,
        /// Its value part.
        value: String,
    },
    /// No parameter has that name.
    Unknown {
        /// The whole override.
        given: String,
        /// Its name part.
        name: String,
    },
    /// The resulting parameters are out of range.
    Invalid(ParamError),
}

impl std::fmt::Display for OverrideError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OverrideError::Syntax(o) => write!(f, "--param {o}: expected NAME=VALUE"),
            OverrideError::NotANumber { given, value } => {
                write!(f, "--param {given}: {value} is not a number")
            }
            OverrideError::Unknown { given, name } => {
                let known: Vec<&str> = PARAMS.iter().map(|i| i.name).collect();
                write!(
                    f,
                    "--param {given}: unknown parameter `{name}` (one of {})",
                    known.join(", ")
                )
            }
            OverrideError::Invalid(e) => write!(f, "--param {e}"),
        }
    }
}

impl std::error::Error for OverrideError {}

/// Parses `NAME=VALUE` overrides (the scene files' names) into [`ParamOverrides`].
pub fn parse_overrides(overrides: &[String]) -> Result<ParamOverrides, OverrideError> {
    let mut out = Vec::new();
    for o in overrides {
        let (name, value) = o
            .split_once('=')
            .ok_or_else(|| OverrideError::Syntax(o.clone()))?;
        let v: f64 = value
            .trim()
            .parse()
            .map_err(|_| OverrideError::NotANumber {
                given: o.clone(),
                value: value.to_string(),
            })?;
        let info = Params::info(name.trim()).ok_or_else(|| OverrideError::Unknown {
            given: o.clone(),
            name: name.trim().to_string(),
        })?;
        out.push((info.name, v));
    }
    Ok(ParamOverrides(out))
}

/// Applies `NAME=VALUE` overrides to `base`, then validates the result.
pub fn override_params(base: Params, overrides: &[String]) -> Result<Params, OverrideError> {
    let p = parse_overrides(overrides)?.apply_to(base);
    p.validate().map_err(OverrideError::Invalid)?;
    Ok(p)
}
