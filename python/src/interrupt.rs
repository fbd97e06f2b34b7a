//! Long calls that Ctrl-C stops: the work runs on a worker thread with the GIL released while
//! the calling thread checks Python's signals every few milliseconds; on an interrupt the
//! planner's [`Cancel`] flag is raised (the search, the noise samples and the play watch it
//! and run out within a batch of shots) and the `KeyboardInterrupt` is raised once the worker
//! has stopped. Without this, Python sees the signal only when the call returns: a frame at
//! the default effort took half a minute to answer Ctrl-C.

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use snooker_planner::Cancel;
use std::time::Duration;

/// How often the calling thread looks for a signal.
const POLL: Duration = Duration::from_millis(20);

/// Runs `work` (which watches `cancel`) so that Ctrl-C interrupts it: its value, or the
/// interrupt (any exception a signal handler raised).
pub fn run<T: Send>(
    py: Python<'_>,
    cancel: &Cancel,
    work: impl FnOnce() -> T + Send,
) -> PyResult<T> {
    std::thread::scope(|scope| {
        let worker = scope.spawn(work);
        loop {
            let finished = py.detach(|| {
                let until = std::time::Instant::now() + POLL;
                while !worker.is_finished() && std::time::Instant::now() < until {
                    std::thread::sleep(Duration::from_millis(1));
                }
                worker.is_finished()
            });
            if finished {
                break;
            }
            if let Err(interrupt) = py.check_signals() {
                cancel.cancel();
                // The work is void: wait for it to run out, then raise the interrupt.
                let _ = py.detach(|| worker.join());
                return Err(interrupt);
            }
        }
        py.detach(|| worker.join())
            .map_err(|_| PyRuntimeError::new_err("internal error: the work panicked"))
    })
}
