//! Model files: `[params]` and `[models]` tables as in a scene, nothing else (the discrepancy
//! workflow's `--model`).

use crate::file::{ModelSpec, ParamOverrides};
use crate::{SceneError, toml_input};
use serde::Deserialize;
use snooker_engine::{Models, Params};

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct ModelFile {
    #[serde(default)]
    params: ParamOverrides,
    #[serde(default)]
    models: ModelSpec,
}

impl ModelSpec {
    /// `base` with the models given replaced.
    pub fn apply_to(&self, base: Models) -> Models {
        Models {
            ball_ball: self.ball_ball.unwrap_or(base.ball_ball),
            cushion: self.cushion.unwrap_or(base.cushion),
        }
    }
}

/// Parses a model file and applies it on top of `params` and `models`; `file` names it in
/// error messages.
pub fn parse_model(
    text: &str,
    file: &str,
    params: Params,
    models: Models,
) -> Result<(Params, Models), SceneError> {
    let spec: ModelFile = toml_input::from_toml(text, file)?;
    let p = spec.params.apply_to(params);
    p.validate()
        .map_err(|e| SceneError::new(file, &format!("params.{}", e.name), e.reason))?;
    Ok((p, spec.models.apply_to(models)))
}
