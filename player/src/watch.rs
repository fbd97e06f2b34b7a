//! Watching the player think: the shots simulated so far (for a progress bar) and a flag that
//! stops the work (a user's cancel button, a server's wall-time limit). The flag is the
//! planner's [`Cancel`]: the planner problems of a decision watch it too, so the search, the
//! noise samples and the play all run out within a batch of shots once it is raised; a
//! decision or a play cut short is void ([`crate::ChooseError::Cancelled`]). The player
//! ([`crate::Player`]) counts and checks it; the greedy baseline ([`crate::Greedy`], a few
//! hundred shots a stroke) does neither, and [`crate::play`] checks it between strokes.

use snooker_planner::Cancel;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

/// The shots counter and the cancellation flag of a play or a decision; clones share both.
/// The default watches nothing in particular: it is never raised unless someone holds a clone.
#[derive(Debug, Clone, Default)]
pub struct Watch {
    cancel: Cancel,
    shots: Arc<AtomicU64>,
}

impl Watch {
    /// A fresh counter watching `cancel`.
    pub fn with_cancel(cancel: Cancel) -> Watch {
        Watch {
            cancel,
            shots: Arc::default(),
        }
    }

    /// The cancellation flag (to hand to planner problems).
    pub fn cancel_flag(&self) -> &Cancel {
        &self.cancel
    }

    /// Raises the flag: the work watching it stops.
    pub fn cancel(&self) {
        self.cancel.cancel();
    }

    /// True once the flag is raised.
    pub fn is_cancelled(&self) -> bool {
        self.cancel.is_cancelled()
    }

    /// Shots simulated so far (every decision watched, added up).
    pub fn shots(&self) -> u64 {
        self.shots.load(Ordering::Relaxed)
    }

    /// Counts `n` more shots simulated.
    pub(crate) fn count(&self, n: u64) {
        self.shots.fetch_add(n, Ordering::Relaxed);
    }
}

/// Two watches are equal when they share their flag and their counter.
impl PartialEq for Watch {
    fn eq(&self, other: &Watch) -> bool {
        Arc::ptr_eq(&self.shots, &other.shots) && self.cancel.same(&other.cancel)
    }
}
