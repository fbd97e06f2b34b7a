//! Candidate events in a binary heap keyed by (time, kind, balls, feature), so that ties are
//! broken in a fixed order. A candidate remembers the generation of each ball it was computed
//! from and is dropped when popped if either ball has changed since (lazy invalidation).

use std::cmp::{Ordering, Reverse};
use std::collections::BinaryHeap;

/// What a candidate event is, with the ball or table feature it involves besides its first
/// ball. Candidates at the same time are taken in the order of the variants here.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Candidate {
    /// The first ball touches ball `other`.
    BallBall {
        /// The second ball.
        other: usize,
    },
    /// The ball touches a straight nose or facing (index into `Table::cushions`).
    Nose {
        /// Index into `Table::cushions`.
        cushion: usize,
    },
    /// The ball touches a jaw.
    Jaw {
        /// Index into `Table::jaws`.
        jaw: usize,
    },
    /// The ball enters a pocket's fall.
    Pocket {
        /// Index into `Table::pockets`.
        pocket: usize,
    },
    /// The ball, in the air, passes over a straight nose with its lowest point above it: it
    /// leaves the table.
    OverCushion {
        /// Index into `Table::cushions`.
        cushion: usize,
    },
    /// The ball, in the air, passes over a jaw's rounded edge with its lowest point above it:
    /// it leaves the table.
    OverJaw {
        /// Index into `Table::jaws`.
        jaw: usize,
    },
    /// The ball, in the air over a pocket's fall, reaches the far half of the fall's edge with
    /// its lowest point above the nose: it clears the pocket's back and leaves the table.
    OverPocket {
        /// Index into `Table::pockets`.
        pocket: usize,
    },
    /// The ball's motion law ends.
    Transition,
}

impl Candidate {
    /// The other ball, for a ball-ball candidate.
    pub fn other_ball(self) -> Option<usize> {
        match self {
            Candidate::BallBall { other } => Some(other),
            _ => None,
        }
    }

    /// (rank of the kind, the other ball, the feature): the order among candidates of the same
    /// time, after the kind and before the feature the first ball.
    fn order(self) -> (u8, Option<usize>, usize) {
        match self {
            Candidate::BallBall { other } => (0, Some(other), 0),
            Candidate::Nose { cushion } => (1, None, cushion),
            Candidate::Jaw { jaw } => (2, None, jaw),
            Candidate::Pocket { pocket } => (3, None, pocket),
            Candidate::OverCushion { cushion } => (4, None, cushion),
            Candidate::OverJaw { jaw } => (5, None, jaw),
            Candidate::OverPocket { pocket } => (6, None, pocket),
            Candidate::Transition => (7, None, 0),
        }
    }
}

/// A scheduled candidate event.
#[derive(Clone, Copy, Debug)]
pub struct Entry {
    /// Absolute time, s.
    pub t: f64,
    /// What it is.
    pub kind: Candidate,
    /// The (first) ball.
    pub a: usize,
    /// Generation of `a` when computed.
    pub gen_a: u64,
    /// Generation of the other ball when computed (0 without one).
    pub gen_b: u64,
}

impl Entry {
    /// Ties are broken by kind, first ball, second ball, feature.
    fn key(&self) -> (u8, usize, Option<usize>, usize) {
        let (rank, other, feature) = self.kind.order();
        (rank, self.a, other, feature)
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
}
