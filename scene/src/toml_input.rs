//! Reading TOML into typed specs, with errors that name the file, the dotted key, the line and
//! the column. Shared by every TOML input: scenes, model files, measured-data files.

use crate::SceneError;

/// 1-based line and column of byte `offset` in `text`.
fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

/// Deserializes TOML `text` into `T`, with errors naming `file`, the key, line and column.
pub fn from_toml<T: serde::de::DeserializeOwned>(text: &str, file: &str) -> Result<T, SceneError> {
    let de = toml::de::Deserializer::parse(text).map_err(|e| {
        let at = e.span().map(|s| line_col(text, s.start));
        let reason = match at {
            Some((l, c)) => format!("not valid TOML (line {l}, column {c}): {}", e.message()),
            None => format!("not valid TOML: {}", e.message()),
        };
        SceneError::new(file, "", reason)
    })?;
    serde_path_to_error::deserialize(de).map_err(|e| {
        let key = e.path().to_string();
        let inner = e.into_inner();
        let mut reason = inner.message().trim().to_string();
        if let Some((l, c)) = inner.span().map(|s| line_col(text, s.start)) {
            reason = format!("{reason} (line {l}, column {c})");
        }
        SceneError::new(file, if key == "." { "" } else { &key }, reason)
    })
}
