//! One module per command: its arguments (clap) and what it does. The physics is the engine's;
//! the formats are the scene crate's; a command reads its input, runs them and writes.

pub mod discrepancy;
pub mod impact;
pub mod simulate;
pub mod synth;
pub mod validate;

use std::process::ExitCode;

/// Exit code for bad input (scene file, arguments): one message, nothing written.
pub const BAD_INPUT: u8 = 2;
/// Exit code for a run that could not finish (a simulation that did not end, a failed
/// verdict).
pub const FAILED: u8 = 1;

/// Prints `error: {message}` and returns the bad-input exit code.
pub fn bad_input(message: impl std::fmt::Display) -> ExitCode {
    eprintln!("error: {message}");
    ExitCode::from(BAD_INPUT)
}

/// Prints `error: {message}` and returns the failure exit code.
pub fn failed(message: impl std::fmt::Display) -> ExitCode {
    eprintln!("error: {message}");
    ExitCode::from(FAILED)
}
