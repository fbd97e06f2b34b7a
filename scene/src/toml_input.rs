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
    serde_path_to_error::deserialize(crate::tables::Tables(de)).map_err(|e| {
        let key = e.path().to_string();
        let inner = e.into_inner();
        let mut reason = inner.message().trim().to_string();
        if let Some((l, c)) = inner.span().map(|s| line_col(text, s.start)) {
            reason = format!("{reason} (line {l}, column {c})");
        }
        SceneError::new(file, if key == "." { "" } else { &key }, reason)
    })
}

/// One step of a dotted key: a table's key or an array's index.
enum Step<'a> {
    Key(&'a str),
    Index(usize),
}

/// The steps of a dotted key as the errors write it (`frame.on`, `balls[2].pos`), or `None`
/// if it is not one.
fn steps(key: &str) -> Option<Vec<Step<'_>>> {
    let mut out = Vec::new();
    for part in key.split('.') {
        let (name, mut rest) = part.split_at(part.find('[').unwrap_or(part.len()));
        if !name.is_empty() {
            out.push(Step::Key(name));
        }
        while let Some(inner) = rest.strip_prefix('[') {
            let end = inner.find(']')?;
            out.push(Step::Index(inner[..end].parse().ok()?));
            rest = &inner[end + 1..];
        }
        if !rest.is_empty() {
            return None;
        }
    }
    Some(out)
}

/// 1-based line and column of the value at the dotted `key` (`frame.on`, `balls[2].pos`) in
/// TOML `text`, or `None` if the text does not parse or has no such key: for checks made
/// after the file was read, so that their messages point at the line as the parser's do.
///
/// ```
/// let text = "[[balls]]\nid = \"cue\"\npos = [0.5, 0.6]\n[frame]\non = \"red\"\n";
/// assert_eq!(snooker_scene::key_position(text, "frame.on"), Some((5, 6)));
/// assert_eq!(snooker_scene::key_position(text, "balls[0].pos"), Some((3, 7)));
/// assert_eq!(snooker_scene::key_position(text, "frame.scores"), None);
/// ```
pub fn key_position(text: &str, key: &str) -> Option<(usize, usize)> {
    use toml::de::{DeTable, DeValue};
    let root = DeValue::Table(DeTable::parse(text).ok()?.into_inner());
    let mut value = &root;
    let mut at = None;
    for step in steps(key)? {
        let next = match step {
            Step::Key(k) => value.get(k)?,
            Step::Index(i) => value.get(i)?,
        };
        at = Some(next.span().start);
        value = next.get_ref();
    }
    at.map(|offset| line_col(text, offset))
}
