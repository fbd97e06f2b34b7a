//! The validation scene set (TOML scene files in `validation/scenes/`, built into the binary)
//! and which impact models each scene runs with.

use serde_json::json;
use snooker_engine::{BallBallModel, CushionModel, Models};

/// `(file name, text)` pairs of scene files of `validation/scenes/`, by stem.
macro_rules! scene_files {
    ($($stem:literal),* $(,)?) => {
        &[$((concat!($stem, ".toml"), include_str!(concat!("../scenes/", $stem, ".toml")))),*]
    };
}

/// The scene files of `validation/scenes/`: (file name, text).
pub const BUILTIN: &[(&str, &str)] = scene_files!(
    "stun",
    "screw",
    "follow",
    "sidespin",
    "cushion-15",
    "cushion-15-spin",
    "cushion-30",
    "cushion-30-spin",
    "cushion-45",
    "cushion-45-spin",
    "cushion-60",
    "cushion-60-spin",
    "cushion-90",
    "cushion-90-spin",
    "cushion-hard-90",
    "cushion-hard-45-spin",
    "head-on-stun",
    "head-on-roll",
    "cut-30",
    "cut-60",
    "combination",
    "break-off",
    "corner-topspin-side",
    "corner-backspin-side",
    "corner-backspin-side-jaws",
    "jaw-middle-spin",
    "jaw-corner-slow",
    "jaw-corner-pot",
    "hop-follow",
    "hop-screw",
    "jump-backspin-side",
    "jump-topspin-side",
);

/// The impact models a scene is run with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ImpactModels {
    /// The frictionless limit: both engines must agree tightly.
    Frictionless,
    /// The thesis's frictional 3D models (section 6.1, 6.2): the difference is measured.
    Mathavan,
    /// The thesis's frictional ball-ball model and the compliant cushion (issue 25); rapier's
    /// cushions get the compliant cushion's restitution for each impact's normal speed.
    Compliant,
}

impl ImpactModels {
    /// Both choices, in report order.
    pub const ALL: [ImpactModels; 3] = [
        ImpactModels::Frictionless,
        ImpactModels::Mathavan,
        ImpactModels::Compliant,
    ];

    /// The name used in scene files and reports.
    pub fn name(self) -> &'static str {
        match self {
            ImpactModels::Frictionless => "frictionless",
            ImpactModels::Mathavan => "mathavan",
            ImpactModels::Compliant => "compliant",
        }
    }

    /// The engine's models of this name, looked up by their scene-file names, or why they are
    /// not available (the engine does not have them yet).
    pub fn models(self) -> Result<Models, String> {
        let name = self.name();
        // The compliant set pairs the frictional ball-ball model with the compliant cushion.
        let ball_name = match self {
            ImpactModels::Compliant => ImpactModels::Mathavan.name(),
            _ => name,
        };
        let ball_ball: BallBallModel = serde_json::from_value(json!(ball_name))
            .map_err(|_| format!("ball-ball model \"{name}\" is not in snooker-engine yet"))?;
        let cushion: CushionModel = serde_json::from_value(json!(name))
            .map_err(|_| format!("cushion model \"{name}\" is not in snooker-engine yet"))?;
        Ok(Models { ball_ball, cushion })
    }

    /// True when the impacts have friction.
    pub fn friction(self) -> bool {
        self != ImpactModels::Frictionless
    }

    /// True when the cushion is the compliant one.
    pub fn compliant_cushion(self) -> bool {
        self == ImpactModels::Compliant
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_model_set_exists() {
        assert_eq!(
            ImpactModels::Frictionless.models().unwrap(),
            Models {
                ball_ball: BallBallModel::Frictionless,
                cushion: CushionModel::Frictionless,
            }
        );
        assert_eq!(
            ImpactModels::Mathavan.models().unwrap(),
            Models {
                ball_ball: BallBallModel::Mathavan,
                cushion: CushionModel::Mathavan,
            }
        );
        assert_eq!(
            ImpactModels::Compliant.models().unwrap(),
            Models {
                ball_ball: BallBallModel::Mathavan,
                cushion: CushionModel::Compliant,
            }
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
