//! Reading a scene given as an in-memory value of any self-describing serde format (a Python
//! dict through pythonize, say) into the same typed specs as a file, with errors that name the
//! file and the dotted key: the values are checked by the scene crate, never by a copy of its
//! rules in another language.

use crate::SceneError;
use serde::{Deserialize, Deserializer};

/// Deserializes `d` into `T`, with errors naming `file` and the key.
pub fn from_value<'de, D, T>(d: D, file: &str) -> Result<T, SceneError>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    serde_path_to_error::deserialize(crate::tables::Tables(d)).map_err(|e| {
        let key = e.path().to_string();
        // "." is the whole value, "?" a place not reached.
        let key = if key == "." || key == "?" { "" } else { &key };
        SceneError::new(file, key, e.into_inner().to_string())
    })
}
