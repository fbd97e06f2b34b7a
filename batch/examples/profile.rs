//! Simulates one of the throughput sets ([`snooker_batch::sets`]) once, on one thread, for a
//! profiler: `cargo build --release -p snooker-batch --example profile`, then
//! `valgrind --tool=callgrind --toggle-collect='snooker_engine::sim::simulate'
//! target/release/examples/profile break-offs` (or `two-ball`). Prints the number of shots and
//! of events, and a hash of every result (unchanged by a change meant to leave every bit alone).

use std::hash::{DefaultHasher, Hash, Hasher};
use std::process::ExitCode;

fn main() -> ExitCode {
    let want = std::env::args().nth(1).unwrap_or_default();
    let sets = snooker_batch::sets::throughput_sets();
    let Some((name, scenes)) = sets
        .iter()
        .find(|(name, _)| name.starts_with(want.as_str()))
    else {
        eprintln!("usage: profile two-ball|break-offs");
        return ExitCode::from(2);
    };
    let shots = match snooker_batch::simulate_many(scenes, Some(1), || {}) {
        Ok(shots) => shots,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let mut hash = DefaultHasher::new();
    let mut events = 0;
    for shot in &shots {
        match shot {
            Ok(s) => {
                events += s.events.len();
                format!("{s:?}").hash(&mut hash);
            }
            Err(e) => e.to_string().hash(&mut hash),
        }
    }
    println!(
        "{name}: {} shots, {events} events, results hash {:016x}",
        shots.len(),
        hash.finish()
    );
    ExitCode::SUCCESS
}
