//! Stopping a plan early: a flag shared between the planner and whoever asked for the plan (a
//! server's job, a user's cancel button). Once raised, every further trial is refused without
//! being simulated, so the search and the noise samples run out at once and the plan returns
//! within a few milliseconds; the caller, who raised the flag, knows the answer is void.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// A cancellation flag; clones share it.
#[derive(Debug, Clone, Default)]
pub struct Cancel(Arc<AtomicBool>);

impl Cancel {
    /// A flag not raised.
    pub fn new() -> Cancel {
        Cancel::default()
    }

    /// Raises the flag: the plans watching it stop.
    pub fn cancel(&self) {
        self.0.store(true, Ordering::Relaxed);
    }

    /// True once raised.
    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }

    /// True when `other` is this flag (a clone of it), not merely in the same state.
    pub fn same(&self, other: &Cancel) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}
