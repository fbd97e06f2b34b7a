//! Reading a scene given as JSON (one object with the scene file's keys: a line of a batch's
//! JSON-lines file, a Python dict) into the same typed specs as TOML, with errors that name the
//! file, the dotted key, the line and the column.

use crate::SceneError;

/// Deserializes JSON `text` into `T`, with errors naming `file`, the key, line and column.
pub fn from_json<T: serde::de::DeserializeOwned>(text: &str, file: &str) -> Result<T, SceneError> {
    let mut de = serde_json::Deserializer::from_str(text);
    let value = serde_path_to_error::deserialize(crate::tables::Tables(&mut de)).map_err(|e| {
        let key = e.path().to_string();
        let inner = e.into_inner();
        let reason = if inner.is_syntax() || inner.is_eof() {
            format!("not valid JSON: {inner}")
        } else {
            inner.to_string()
        };
        // "." is the whole document, "?" a place not reached (the text ended).
        let key = if key == "." || key == "?" { "" } else { &key };
        SceneError::new(file, key, reason)
    })?;
    de.end()
        .map_err(|e| SceneError::new(file, "", format!("not valid JSON: {e}")))?;
    Ok(value)
}
