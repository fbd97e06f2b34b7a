//! The one error every input file of the project reports: which file, which key, and why.

/// An input that cannot be used: which file, which key, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError {
    /// The file (as given by the user).
    pub file: String,
    /// The key at fault, dotted (`balls[2].pos`), or empty when the file itself is at fault.
    pub key: String,
    /// Why.
    pub reason: String,
}

impl SceneError {
    /// An error of `file` at `key` (empty: the file itself).
    pub fn new(file: &str, key: &str, reason: impl Into<String>) -> SceneError {
        SceneError {
            file: file.to_string(),
            key: key.to_string(),
            reason: reason.into(),
        }
    }
}

impl std::fmt::Display for SceneError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.key.is_empty() {
            write!(f, "{}: {}", self.file, self.reason)
        } else {
            write!(f, "{}: key `{}`: {}", self.file, self.key, self.reason)
        }
    }
}

impl std::error::Error for SceneError {}
