//! The `snooker` command-line tool's library: scene files, results and summaries around the
//! physics in `snooker-engine`.

pub mod discrepancy_cmd;
pub mod impact_cmd;
pub mod measured;
pub mod output;
pub mod record;
pub mod scene;
pub mod validate_cmd;
