//! Scene files written from values (the format of `docs/formats.md`), every number so
//! that it reads back to the bit: a number as TOML reads it back ([`num`]), and a scene file
//! with its `[cue]` replaced ([`with_cue`]: `snooker plan --scene-out`). Scenes built from
//! parts are [`crate::SceneFile`]s.

use snooker_engine::Cue;

/// A number as TOML reads it back exactly (Rust's shortest round-trip form).
pub fn num(v: f64) -> String {
    if v.is_nan() {
        "nan".into()
    } else if v.is_infinite() {
        if v > 0.0 { "inf".into() } else { "-inf".into() }
    } else {
        format!("{v:?}")
    }
}

/// Why a scene file could not be written again with a new strike.
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    /// The text is not a TOML table.
    #[error("{0}")]
    NotToml(#[from] toml::de::Error),
    /// The table could not be written as TOML.
    #[error("{0}")]
    Serialize(#[from] toml::ser::Error),
}

/// `scene_text` with its `[cue]` replaced by `cue` on ball `ball` (comments and layout are not
/// kept: the file is written again from its values).
pub fn with_cue(scene_text: &str, ball: &str, cue: &Cue) -> Result<String, WriteError> {
    let mut doc: toml::Table = scene_text.parse()?;
    let mut table = toml::Table::new();
    table.insert("ball".into(), toml::Value::String(ball.into()));
    table.insert("speed".into(), toml::Value::Float(cue.speed));
    table.insert("aim".into(), toml::Value::Float(cue.aim));
    let offset = cue.offset.iter().map(|&v| toml::Value::Float(v)).collect();
    table.insert("offset".into(), toml::Value::Array(offset));
    table.insert("elevation".into(), toml::Value::Float(cue.elevation));
    doc.insert("cue".into(), toml::Value::Table(table));
    Ok(toml::to_string(&doc)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use snooker_engine::rng::Rng;

    #[test]
    fn a_strike_written_again_reads_back_to_the_bit() {
        // Random bit patterns: the generator's state after each draw.
        let mut rng = Rng(0x1234_5678_9abc_def1);
        for _ in 0..2000 {
            rng.uniform(0.0, 1.0);
            let v = f64::from_bits(rng.0);
            if !v.is_finite() {
                continue;
            }
            let cue = Cue {
                speed: v,
                aim: -v,
                offset: [v / 3.0, v * 1e-300],
                elevation: v.abs(),
            };
            let text = with_cue("balls = []", "cue", &cue).unwrap();
            let back: toml::Table = text.parse().unwrap();
            let table = back["cue"].as_table().unwrap();
            let speed = table["speed"].as_float().unwrap();
            assert_eq!(speed.to_bits(), v.to_bits(), "{text}");
            let off = table["offset"].as_array().unwrap();
            assert_eq!(off[1].as_float().unwrap().to_bits(), (v * 1e-300).to_bits());
        }
    }

    #[test]
    fn a_built_scene_written_reads_back_to_the_bit() {
        use crate::{BallSpec, CueSpec, SceneFile};
        let mut rng = Rng(0x5eed_0000_0000_0002);
        for k in 0..500 {
            let x = rng.uniform(0.1, 3.5);
            let y = rng.uniform(0.1, 1.7);
            let v = [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0), 0.0];
            let scene = SceneFile::new()
                .with_name(format!("built {k}"))
                .with_param("mu_roll", rng.uniform(0.005, 0.02))
                .with_ball(BallSpec::at("cue", [x, y]))
                .with_ball(BallSpec::at("red", [3.4, 1.6]).with_vel(v))
                .with_strike(
                    CueSpec::new("cue", rng.uniform(0.5, 5.0), rng.uniform(-3.0, 3.0))
                        .with_offset([rng.uniform(-0.005, 0.005), 0.0]),
                );
            let direct = scene.clone().build("built").unwrap();
            let from_toml = crate::parse(&scene.to_toml(), "built").unwrap();
            let from_json = crate::parse_json(&scene.to_json().unwrap(), "built").unwrap();
            assert_eq!(direct.setup, from_toml.setup, "{}", scene.to_toml());
            assert_eq!(direct.setup, from_json.setup);
            assert_eq!(direct.strike, from_toml.strike);
            assert_eq!(direct.name, from_toml.name);
        }
        // An unknown parameter is refused by build as a file's is when read.
        let e = SceneFile::new()
            .with_param("mu_rol", 0.01)
            .with_ball(BallSpec::at("cue", [1.0, 1.0]))
            .build("built")
            .unwrap_err();
        assert_eq!(e.key, "params.mu_rol");
        // A parameter set twice is the last value, written once (it was written twice, and
        // the file read back refused the duplicate key).
        let scene = SceneFile::new()
            .with_ball(BallSpec::at("cue", [1.0, 1.0]))
            .with_param("mu_roll", 0.01)
            .with_param("mu_roll", 0.02);
        let read = crate::parse(&scene.to_toml(), "twice.toml").unwrap();
        assert_eq!(read.setup.params.mu_roll, 0.02);
        assert_eq!(read.setup, scene.build("built").unwrap().setup);
    }
}
