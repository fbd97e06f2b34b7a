//! Many shots at once (issue 14). Scenes come from a directory of scene files or a JSON-lines
//! file ([`input`]); they are simulated on every core, or on as many threads as asked, with
//! the results in input order and bit-identical to simulating them one by one whatever the
//! thread count (each shot is simulated alone, deterministically: [`run`]). Each shot becomes a
//! line of JSON as `snooker simulate --json` writes it, or a row of per-shot summaries
//! ([`summary`]; with the `parquet` feature, a Parquet table: [`table`]). A scene that cannot
//! be read or simulated keeps its place with its error; the others go on.
//!
//! ```
//! let text = r#"{"balls": [{"id": "cue", "pos": [1.0, 0.8]}, {"id": "red", "pos": [2.0, 0.9]}], "cue": {"ball": "cue", "speed": 2.0, "aim": 0.1}}"#;
//! let sources = snooker_batch::input::from_json_lines(&format!("{text}\n{text}\n"), "s.jsonl");
//! let scenes: Vec<_> = sources.iter().map(|s| s.scene().unwrap()).collect();
//! let shots = snooker_batch::simulate_many(&scenes, Some(2), || {}).unwrap();
//! assert_eq!(shots[0].as_ref().unwrap(), shots[1].as_ref().unwrap());
//! let line = snooker_batch::line::json_line(&sources[0].name, &scenes[0], &shots[0]);
//! let json = serde_json::to_value(&line).unwrap();
//! assert_eq!(json["source"], "s.jsonl:1");
//! ```

pub mod input;
pub mod line;
pub mod run;
pub mod sets;
pub mod summary;
#[cfg(feature = "parquet")]
pub mod table;

pub use input::Source;
pub use run::{Outcome, run_sources, simulate_many};
pub use summary::Summary;
