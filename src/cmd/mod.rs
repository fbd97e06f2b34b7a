//! One module per command: its arguments (clap) and what it does. The physics is the engine's;
//! the formats are the scene crate's; a command reads its input, runs them and writes.

/// `println!` to standard output that does not panic when the reader has gone (`| head`):
/// the output is then unwanted, not an error.
macro_rules! outln {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($t)*);
    }};
}

/// `print!` to standard output, likewise.
macro_rules! out {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        let _ = write!(std::io::stdout(), $($t)*);
    }};
}

pub mod batch;
pub mod discrepancy;
pub mod impact;
pub mod plan;
pub mod play;
pub mod referee;
pub mod serve;
pub mod simulate;
pub mod spec;
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

/// Says, unless `quiet`, that the recording `out` was written, on standard error when
/// standard output carries the JSON.
pub fn say_recording_written(out: &std::path::Path, quiet: bool, json_to_stdout: bool) {
    use std::io::Write as _;
    if quiet {
        return;
    }
    let note = format!(
        "recording written to {0} (open it with `rerun {0}`)",
        out.display()
    );
    // Standard output may be carrying the JSON; a closed pipe is no error here.
    let _ = if json_to_stdout {
        writeln!(std::io::stderr(), "{note}")
    } else {
        writeln!(std::io::stdout(), "{note}")
    };
}
