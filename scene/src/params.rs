//! Parameter overrides: a scene's or a model file's `[params]`, or overrides given by name.
//! Names, ranges and sources are the engine's one declaration
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

/// A parameter override that cannot be used.
#[derive(Clone, Debug, PartialEq)]
pub enum OverrideError {
    /// No parameter has that name.
    Unknown {
        /// The name given.
        name: String,
    },
    /// The resulting parameters are out of range.
    Invalid(ParamError),
}

impl OverrideError {
    /// The name of the parameter at fault, as given.
    pub fn name(&self) -> &str {
        match self {
            OverrideError::Unknown { name } => name,
            OverrideError::Invalid(e) => e.name,
        }
    }
}

impl std::fmt::Display for OverrideError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OverrideError::Unknown { name } => {
                let known: Vec<&str> = PARAMS.iter().map(|i| i.name).collect();
                write!(
                    f,
                    "unknown parameter `{name}` (one of {})",
                    known.join(", ")
                )
            }
            OverrideError::Invalid(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for OverrideError {}

/// Overrides by name (the scene files' `[params]` names) as [`ParamOverrides`].
pub fn overrides<S: AsRef<str>>(given: &[(S, f64)]) -> Result<ParamOverrides, OverrideError> {
    given
        .iter()
        .map(|(name, v)| {
            let name = name.as_ref().trim();
            Params::info(name)
                .map(|info| (info.name, *v))
                .ok_or_else(|| OverrideError::Unknown { name: name.into() })
        })
        .collect::<Result<_, _>>()
        .map(ParamOverrides)
}

/// `base` with the parameters named in `given` set to their values, then validated.
pub fn override_params<S: AsRef<str>>(
    base: Params,
    given: &[(S, f64)],
) -> Result<Params, OverrideError> {
    let p = overrides(given)?.apply_to(base);
    p.validate().map_err(OverrideError::Invalid)?;
    Ok(p)
}
