//! Simulating many scenes on a pool of threads (rayon). Each shot is simulated alone by the
//! deterministic engine, so the results are those of one-by-one runs to the bit, whatever the
//! thread count; they come back in input order.

use crate::input::Source;
use rayon::prelude::*;
use snooker_engine::{Shot, SimError};
use snooker_scene::{Scene, SceneError};
use std::borrow::Borrow;

/// A thread count that cannot be used.
#[derive(Debug, thiserror::Error)]
#[error("cannot start {threads} threads: {reason}")]
pub struct ThreadsError {
    /// The count asked for.
    pub threads: usize,
    /// Why.
    pub reason: String,
}

/// What became of one source: its scene (or why it could not be read) and, if read, its shot
/// (or why it could not be simulated).
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The scene read.
    pub scene: Result<Scene, SceneError>,
    /// Its shot; `None` when the scene could not be read.
    pub shot: Option<Result<Shot, SimError>>,
}

impl Outcome {
    /// Why the scene failed, if it did.
    pub fn error(&self) -> Option<String> {
        match (&self.scene, &self.shot) {
            (Err(e), _) => Some(e.to_string()),
            (Ok(_), Some(Err(e))) => Some(e.to_string()),
            _ => None,
        }
    }
}

/// Simulates every scene (owned or shared: anything that borrows as a [`Scene`]), on `threads`
/// threads (all cores if `None`), calling `done` after each shot (for a progress bar): the
/// shots or their errors, in input order.
pub fn simulate_many<S: Borrow<Scene> + Sync>(
    scenes: &[S],
    threads: Option<usize>,
    done: impl Fn() + Sync,
) -> Result<Vec<Result<Shot, SimError>>, ThreadsError> {
    run_on(threads, || {
        scenes
            .par_iter()
            .map(|s| {
                let s = s.borrow();
                let shot = snooker_engine::simulate(&s.setup, &s.options);
                done();
                shot
            })
            .collect()
    })
}

/// Reads and simulates every source, as [`simulate_many`]: the outcomes in input order.
pub fn run_sources(
    sources: &[Source],
    threads: Option<usize>,
    done: impl Fn() + Sync,
) -> Result<Vec<Outcome>, ThreadsError> {
    run_on(threads, || {
        sources
            .par_iter()
            .map(|src| {
                let scene = src.scene();
                let shot = scene
                    .as_ref()
                    .ok()
                    .map(|s| snooker_engine::simulate(&s.setup, &s.options));
                done();
                Outcome { scene, shot }
            })
            .collect()
    })
}

/// The most threads a batch runs on. Each shot is simulated alone, so threads beyond the cores
/// only add their stacks and their switching; a count past this is a typo, and starting it
/// (100,000 threads) took minutes before failing or simulating anything.
pub const MAX_THREADS: usize = 1024;

/// Checks a thread count before any work: at least one, at most [`MAX_THREADS`].
pub fn check_threads(threads: usize) -> Result<(), ThreadsError> {
    let fail = |reason: String| ThreadsError { threads, reason };
    if threads == 0 {
        return Err(fail("at least one is needed".into()));
    }
    if threads > MAX_THREADS {
        return Err(fail(format!("at most {MAX_THREADS} are started")));
    }
    Ok(())
}

/// Runs `work` on a pool of `threads` threads (the global pool, all cores, if `None`).
pub fn run_on<T: Send>(
    threads: Option<usize>,
    work: impl FnOnce() -> T + Send,
) -> Result<T, ThreadsError> {
    match threads {
        None => Ok(work()),
        Some(n) => {
            let fail = |reason: String| ThreadsError { threads: n, reason };
            check_threads(n)?;
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| fail(e.to_string()))?;
            Ok(pool.install(work))
        }
    }
}
