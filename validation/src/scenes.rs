//! The validation scene set (TOML scene files in `validation/scenes/`, built into the binary)
//! and which impact models each scene runs with.

use serde_json::json;
use snooker_engine::{BallBallModel, CushionModel, Models};

/// The scene files of `validation/scenes/`: (file name, text).
pub const BUILTIN: &[(&str, &str)] = &[
    ("stun.toml", include_str!("../scenes/stun.toml")),
    ("screw.toml", include_str!("../scenes/screw.toml")),
    ("follow.toml", include_str!("../scenes/follow.toml")),
    ("sidespin.toml", include_str!("../scenes/sidespin.toml")),
    ("cushion-15.toml", include_str!("../scenes/cushion-15.toml")),
    (
        "cushion-15-spin.toml",
        include_str!("../scenes/cushion-15-spin.toml"),
    ),
    ("cushion-30.toml", include_str!("../scenes/cushion-30.toml")),
    (
        "cushion-30-spin.toml",
        include_str!("../scenes/cushion-30-spin.toml"),
    ),
    ("cushion-45.toml", include_str!("../scenes/cushion-45.toml")),
    (
        "cushion-45-spin.toml",
        include_str!("../scenes/cushion-45-spin.toml"),
    ),
    ("cushion-60.toml", include_str!("../scenes/cushion-60.toml")),
    (
        "cushion-60-spin.toml",
        include_str!("../scenes/cushion-60-spin.toml"),
    ),
    ("cushion-90.toml", include_str!("../scenes/cushion-90.toml")),
    (
        "cushion-90-spin.toml",
        include_str!("../scenes/cushion-90-spin.toml"),
    ),
    (
        "head-on-stun.toml",
        include_str!("../scenes/head-on-stun.toml"),
    ),
    (
        "head-on-roll.toml",
        include_str!("../scenes/head-on-roll.toml"),
    ),
    ("cut-30.toml", include_str!("../scenes/cut-30.toml")),
    ("cut-60.toml", include_str!("../scenes/cut-60.toml")),
    (
        "combination.toml",
        include_str!("../scenes/combination.toml"),
    ),
    ("break-off.toml", include_str!("../scenes/break-off.toml")),
];

/// The impact models a scene is run with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ImpactModels {
    /// The frictionless limit: both engines must agree tightly.
    Frictionless,
    /// The thesis's frictional 3D models (section 6.1, 6.2): the difference is measured.
    Mathavan,
}

impl ImpactModels {
    /// Both choices, in report order.
    pub const ALL: [ImpactModels; 2] = [ImpactModels::Frictionless, ImpactModels::Mathavan];

    /// The name used in scene files and reports.
    pub fn name(self) -> &'static str {
        match self {
            ImpactModels::Frictionless => "frictionless",
            ImpactModels::Mathavan => "mathavan",
        }
    }

    /// The engine's models of this name, looked up by their scene-file names, or why they are
    /// not available (the engine does not have them yet).
    pub fn models(self) -> Result<Models, String> {
        let name = self.name();
        let ball_ball: BallBallModel = serde_json::from_value(json!(name))
            .map_err(|_| format!("ball-ball model \"{name}\" is not in snooker-engine yet"))?;
        let cushion: CushionModel = serde_json::from_value(json!(name))
            .map_err(|_| format!("cushion model \"{name}\" is not in snooker-engine yet"))?;
        Ok(Models { ball_ball, cushion })
    }

    /// True when the impacts have friction.
    pub fn friction(self) -> bool {
        self == ImpactModels::Mathavan
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frictionless_models_exist() {
        assert_eq!(
            ImpactModels::Frictionless.models().unwrap(),
            Models::default()
        );
    }

    #[test]
    fn every_scene_file_is_listed() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
        let mut files: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|f| f.ends_with(".toml"))
            .collect();
        files.sort();
        let mut listed: Vec<String> = BUILTIN.iter().map(|(f, _)| f.to_string()).collect();
        listed.sort();
        assert_eq!(files, listed);
    }
}
