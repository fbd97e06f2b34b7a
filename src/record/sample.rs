//! Where and what a recording samples: a fixed-rate grid plus every event instant taken twice
//! (just before and just after), and the exact states there (the balls' orientations there:
//! `snooker_engine::sim::orientation`).

use snooker_engine::{BallState, Shot};

/// Why a sample was taken.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// A point of the fixed-rate grid (or the end of the shot).
    Grid,
    /// The state just before the events of group `.0` (see [`Schedule::groups`]).
    Before(usize),
    /// The state just after the events of group `.0`.
    After(usize),
}

/// One sample instant, shared by every ball.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Instant {
    /// Simulated time, s.
    pub t: f64,
    /// Grid point, or which side of an event instant.
    pub side: Side,
}

/// The sample instants of a shot, in time order (a `Before` and its `After` share their time).
#[derive(Clone, Debug, PartialEq)]
pub struct Schedule {
    /// The instants.
    pub instants: Vec<Instant>,
    /// Events grouped by identical time: `(t, first event index, one past the last)`.
    pub groups: Vec<(f64, usize, usize)>,
}

impl Schedule {
    /// Grid `k / rate` for every `k` with `k / rate <= duration`, the end of the shot, and every
    /// distinct event time twice; a grid point equal to an event time is covered by the pair.
    pub fn new(shot: &Shot, rate: f64) -> Schedule {
        let mut groups: Vec<(f64, usize, usize)> = Vec::new();
        for (i, e) in shot.events.iter().enumerate() {
            match groups.last_mut() {
                Some(g) if g.0 == e.t => g.2 = i + 1,
                _ => groups.push((e.t, i, i + 1)),
            }
        }
        let mut grid: Vec<f64> = (0u64..)
            .map(|k| k as f64 / rate)
            .take_while(|&t| t <= shot.duration)
            .collect();
        if grid.last() != Some(&shot.duration) {
            grid.push(shot.duration);
        }
        let mut instants = Vec::with_capacity(grid.len() + 2 * groups.len());
        let mut g = 0;
        for &t in &grid {
            while g < groups.len() && groups[g].0 <= t {
                instants.push(Instant {
                    t: groups[g].0,
                    side: Side::Before(g),
                });
                instants.push(Instant {
                    t: groups[g].0,
                    side: Side::After(g),
                });
                g += 1;
            }
            if instants.last().is_none_or(|i| i.t != t) {
                instants.push(Instant {
                    t,
                    side: Side::Grid,
                });
            }
        }
        Schedule { instants, groups }
    }

    /// Ball `ball`'s state at every instant: the exact trajectory, and at a `Before` instant
    /// the `before` state of the first event of the group that involves the ball (the
    /// trajectory itself gives the state after an instant's events).
    pub fn states(&self, shot: &Shot, ball: usize) -> Vec<BallState> {
        let track = &shot.tracks[ball];
        self.instants
            .iter()
            .map(|i| {
                if let Side::Before(g) = i.side {
                    let (_, lo, hi) = self.groups[g];
                    let before = shot.events[lo..hi].iter().find_map(|e| {
                        let k = e.balls.iter().position(|&b| b == ball)?;
                        e.before.get(k).copied()
                    });
                    if let Some(s) = before {
                        return s;
                    }
                }
                track.state_at(i.t, &shot.params)
            })
            .collect()
    }
}
