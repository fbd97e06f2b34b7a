//! Candidate events in a binary heap keyed by (time, kind, balls, feature), so that ties are
//! broken in a fixed order. A candidate remembers the generation of each ball it was computed
//! from and is dropped when popped if either ball has changed since (lazy invalidation).

use std::cmp::{Ordering, Reverse};
use std::collections::BinaryHeap;

/// Kinds of candidate, in the order they are taken when their times are equal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Candidate {
    /// Two balls touch.
    BallBall,
    /// A ball touches a straight nose or facing (index into `Table::cushions`).
    Nose,
    /// A ball touches a jaw (index into `Table::jaws`).
    Jaw,
    /// A ball enters a pocket's fall (index into `Table::pockets`).
    Pocket,
    /// A ball's motion law ends.
    Transition,
}

/// A scheduled candidate event.
#[derive(Clone, Copy, Debug)]
pub struct Entry {
    /// Absolute time, s.
    pub t: f64,
    /// Kind.
    pub kind: Candidate,
    /// First ball.
    pub a: usize,
    /// Second ball for ball-ball, else `usize::MAX`.
    pub b: usize,
    /// Table feature index, or 0.
    pub feature: usize,
    /// Generation of `a` when computed.
    pub gen_a: u64,
    /// Generation of `b` when computed.
    pub gen_b: u64,
}

impl Entry {
    fn key(&self) -> (Candidate, usize, usize, usize) {
        (self.kind, self.a, self.b, self.feature)
    }
}

impl PartialEq for Entry {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Entry {}

impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Entry {
    fn cmp(&self, other: &Self) -> Ordering {
        self.t
            .total_cmp(&other.t)
            .then_with(|| self.key().cmp(&other.key()))
    }
}

/// Min-queue of candidates.
#[derive(Default)]
pub struct Queue {
    heap: BinaryHeap<Reverse<Entry>>,
}

impl Queue {
    /// Adds a candidate.
    pub fn push(&mut self, e: Entry) {
        self.heap.push(Reverse(e));
    }

    /// Removes and returns the earliest candidate.
    pub fn pop(&mut self) -> Option<Entry> {
        self.heap.pop().map(|Reverse(e)| e)
    }

    /// Number of queued candidates (stale ones included).
    pub fn len(&self) -> usize {
        self.heap.len()
    }

    /// True when nothing is queued.
    pub fn is_empty(&self) -> bool {
        self.heap.is_empty()
    }
}
