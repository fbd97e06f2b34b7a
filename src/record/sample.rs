//! Where and what a recording samples: a fixed-rate grid plus every event instant taken twice
//! (just before and just after), and the exact states there (the balls' orientations there:
//! `snooker_engine::sim::orientation`).

use snooker_engine::sim::Track;
use snooker_engine::{BallState, Params, Shot};

/// The times to draw ball `ball`'s way in `shot` at, struck at cue speed `speed` (m/s): the
/// start, the end, every event it took part in (where its way turns, or a curve begins or
/// ends) and about every 5 cm of its way between (a curve's shape), in time order. A line
/// through these keeps every corner; evenly spaced times cut them.
pub fn way_times(shot: &Shot, ball: usize, speed: f64) -> Vec<f64> {
    let mut times: Vec<f64> = vec![0.0, shot.duration];
    times.extend(
        shot.events
            .iter()
            .filter(|e| e.balls.contains(&ball))
            .map(|e| e.t),
    );
    let step = 0.05 / speed.max(0.1);
    let mut t = step;
    while t < shot.duration {
        times.push(t);
        t += step;
    }
    times.sort_by(f64::total_cmp);
    times.dedup();
    times
}

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
    /// Events grouped by identical time: `(t, first event index, one past the last)`; a cut
    /// with no event at its time is a group of no events.
    pub groups: Vec<(f64, usize, usize)>,
    /// The cuts (see [`Schedule::with_cuts`]), in time order.
    pub cuts: Vec<f64>,
}

impl Schedule {
    /// Grid `k / rate` for every `k` with `k / rate <= duration`, the end of the shot, and every
    /// distinct event time twice; a grid point equal to an event time is covered by the pair.
    pub fn new(shot: &Shot, rate: f64) -> Schedule {
        Schedule::with_cuts(shot, rate, &[])
    }

    /// As [`Schedule::new`], and every time of `cuts` twice as well: instants where the balls
    /// change with no event (the start of each stroke of a sequence: a ball struck, respotted
    /// or placed in hand), so that the state just before and just after are both sampled.
    pub fn with_cuts(shot: &Shot, rate: f64, cuts: &[f64]) -> Schedule {
        let mut groups: Vec<(f64, usize, usize)> = Vec::new();
        for (i, e) in shot.events.iter().enumerate() {
            match groups.last_mut() {
                Some(g) if g.0 == e.t => g.2 = i + 1,
                _ => groups.push((e.t, i, i + 1)),
            }
        }
        let mut cuts = cuts.to_vec();
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        for &t in &cuts {
            let at = groups.partition_point(|g| g.0 < t);
            if groups.get(at).is_none_or(|g| g.0 != t) {
                let first = groups.get(at).map_or(shot.events.len(), |g| g.1);
                groups.insert(at, (t, first, first));
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
        Schedule {
            instants,
            groups,
            cuts,
        }
    }

    /// Ball `ball`'s state at every instant: the exact trajectory, and at a `Before` instant
    /// the `before` state of the first event of the group that involves the ball, or at a cut
    /// the state its track held up to the cut (the trajectory itself gives the state after an
    /// instant's events).
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
                    if self.cuts.binary_search_by(|c| c.total_cmp(&i.t)).is_ok() {
                        return held_before(track, i.t, &shot.params);
                    }
                }
                track.state_at(i.t, &shot.params)
            })
            .collect()
    }
}

/// The state `track` held just before `t`: its latest segment starting before `t`, at `t`.
fn held_before(track: &Track, t: f64, p: &Params) -> BallState {
    match track.segments.partition_point(|s| s.t < t).checked_sub(1) {
        Some(i) => {
            let seg = &track.segments[i];
            snooker_engine::motion::state_at(&seg.state, t - seg.t, p)
        }
        None => track.state_at(t, p),
    }
}
