//! Where a batch's scenes come from: every scene file (`*.toml`) of a directory, in file-name
//! order, or a JSON-lines file, one scene object per line with the scene file's keys (blank
//! lines skipped). Sources are listed first and parsed when simulated, so that a batch of
//! millions holds only its current chunk of scenes; one that does not parse keeps its place
//! with its error.

use snooker_scene::{Scene, SceneError};
use std::path::{Path, PathBuf};

/// One scene of a batch, not yet read.
#[derive(Debug, Clone)]
pub struct Source {
    /// Where it came from: the file's path, or `FILE:LINE` for a JSON line.
    pub name: String,
    text: Text,
}

#[derive(Debug, Clone)]
enum Text {
    File(PathBuf),
    JsonLine(String),
}

impl Source {
    /// A scene given as one JSON object (the scene file's keys), named `name`.
    pub fn json(name: &str, text: &str) -> Source {
        Source {
            name: name.into(),
            text: Text::JsonLine(text.into()),
        }
    }

    /// The scene, or why it cannot be read.
    pub fn scene(&self) -> Result<Scene, SceneError> {
        match &self.text {
            Text::File(p) => snooker_scene::load(p),
            Text::JsonLine(l) => snooker_scene::parse_json(l, &self.name),
        }
    }
}

/// A batch's input that cannot be read at all (the path, not a scene in it).
#[derive(Debug, thiserror::Error)]
pub enum InputError {
    /// The path does not exist or cannot be read.
    #[error("{path}: {reason}")]
    Unreadable {
        /// The path given.
        path: String,
        /// Why.
        reason: String,
    },
    /// Neither a directory nor a JSON-lines file.
    #[error("{0}: not a directory of scene files (*.toml) nor a JSON-lines file (*.jsonl)")]
    Kind(String),
    /// No scene in it.
    #[error("{0}: no scenes in it (a directory needs *.toml files, a JSON-lines file lines)")]
    Empty(String),
}

/// The scenes of a directory (its `*.toml` entries, by file name, the extension in any case;
/// one that cannot be read is still a scene, to fail with its reason) or a JSON-lines file
/// (`*.jsonl`, `*.ndjson`).
pub fn read(path: &Path) -> Result<Vec<Source>, InputError> {
    let shown = path.display().to_string();
    let unreadable = |e: std::io::Error| InputError::Unreadable {
        path: shown.clone(),
        reason: e.to_string(),
    };
    let sources = if path.is_dir() {
        let mut files: Vec<_> = std::fs::read_dir(path)
            .map_err(unreadable)?
            .filter_map(|e| e.ok().map(|e| e.path()))
            // Every `*.toml` entry, whatever it is: one that cannot be read (a dangling link,
            // a directory) gets its error row rather than vanishing from the run.
            .filter(|p| {
                p.extension()
                    .is_some_and(|x| x.eq_ignore_ascii_case("toml"))
            })
            .collect();
        files.sort();
        files
            .into_iter()
            .map(|f| Source {
                name: f.display().to_string(),
                text: Text::File(f),
            })
            .collect()
    } else if path
        .extension()
        .is_some_and(|x| x.eq_ignore_ascii_case("jsonl") || x.eq_ignore_ascii_case("ndjson"))
    {
        from_json_lines(&snooker_scene::read_text(path).map_err(unreadable)?, &shown)
    } else if path.exists() {
        return Err(InputError::Kind(shown));
    } else {
        return Err(InputError::Unreadable {
            path: shown,
            reason: "no such file or directory".into(),
        });
    };
    if sources.is_empty() {
        return Err(InputError::Empty(shown));
    }
    Ok(sources)
}

/// The scenes of JSON-lines `text` (file `file`), one per non-blank line, named `FILE:LINE`.
pub fn from_json_lines(text: &str, file: &str) -> Vec<Source> {
    text.lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(i, l)| Source::json(&format!("{file}:{}", i + 1), l))
        .collect()
}
