//! The scene with the planned strike as its `[cue]` table: `snooker simulate` on it replays
//! the planned shot to the bit (every number is written so that it reads back exactly).

use crate::StrikeSpec;

/// `scene_text` with its `[cue]` replaced by `strike` (comments and layout are not kept: the
/// file is written again from its values). Errors if the text is not a TOML table.
pub fn with_strike(scene_text: &str, strike: &StrikeSpec) -> Result<String, String> {
    let mut doc: toml::Table = scene_text.parse().map_err(|e| format!("{e}"))?;
    let mut cue = toml::Table::new();
    cue.insert("ball".into(), toml::Value::String(strike.ball.clone()));
    cue.insert("speed".into(), toml::Value::Float(strike.speed));
    cue.insert("aim".into(), toml::Value::Float(strike.aim));
    cue.insert(
        "offset".into(),
        toml::Value::Array(
            strike
                .offset
                .iter()
                .map(|&v| toml::Value::Float(v))
                .collect(),
        ),
    );
    cue.insert("elevation".into(), toml::Value::Float(strike.elevation));
    doc.insert("cue".into(), toml::Value::Table(cue));
    toml::to_string(&doc).map_err(|e| format!("{e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_back_to_the_bit() {
        let mut x = 0x1234_5678_9abc_def1u64;
        for _ in 0..2000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let v = f64::from_bits(x);
            if !v.is_finite() {
                continue;
            }
            let s = StrikeSpec {
                ball: "cue".into(),
                speed: v,
                aim: -v,
                offset: [v / 3.0, v * 1e-300],
                elevation: v.abs(),
            };
            let text = with_strike("balls = []", &s).unwrap();
            let back: toml::Table = text.parse().unwrap();
            let cue = back["cue"].as_table().unwrap();
            assert_eq!(
                cue["speed"].as_float().unwrap().to_bits(),
                v.to_bits(),
                "{text}"
            );
            let off = cue["offset"].as_array().unwrap();
            assert_eq!(off[1].as_float().unwrap().to_bits(), (v * 1e-300).to_bits());
        }
    }
}
