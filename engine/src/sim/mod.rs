//! The event loop.
//!
//! Each ball is kept as a state at its own reference time plus the law it follows, and is
//! evaluated on demand; an event only advances the balls it touches. After an event on balls S
//! their generations are bumped and only their candidates are recomputed: the end of their
//! law, their cushion, jaw and pocket contacts, and their contacts with every other ball, each
//! searched only within the window where both laws hold. Stale candidates are dropped when
//! popped.

pub mod error;
pub mod event;
pub mod queue;
pub mod setup;
pub mod shot;

use crate::ball::{BallState, Motion, Vec3};
use crate::detect;
use crate::motion;
use crate::params::Params;
pub use error::SimError;
pub use event::{Event, EventKind};
use queue::{Candidate, Entry, Queue};
pub use setup::{Setup, SetupError, SimOptions};
pub use shot::{Ending, Segment, Shot, Stats, Track};

/// What resolving a candidate gives: the event's kind, the balls involved, their states
/// before and after, the feature involved and the normal approach speed.
type Resolved = (
    EventKind,
    Vec<usize>,
    Vec<BallState>,
    Vec<BallState>,
    Option<String>,
    Option<f64>,
);

struct Live {
    /// State at `t_ref`.
    state: BallState,
    t_ref: f64,
    /// Absolute time at which the current law ends.
    law_end: f64,
    generation: u64,
}

struct Sim<'a> {
    setup: &'a Setup,
    opts: SimOptions,
    balls: Vec<Live>,
    queue: Queue,
    now: f64,
    events: Vec<Event>,
    tracks: Vec<Track>,
    stats: Stats,
}

/// Simulates a shot from `setup` until every ball rests (or the horizon).
pub fn simulate(setup: &Setup, opts: &SimOptions) -> Result<Shot, SimError> {
    setup.validate().map_err(SimError::Setup)?;
    let p = &setup.params;
    let mut sim = Sim {
        setup,
        opts: *opts,
        balls: Vec::with_capacity(setup.balls.len()),
        queue: Queue::default(),
        now: 0.0,
        events: Vec::new(),
        tracks: Vec::with_capacity(setup.balls.len()),
        stats: Stats::default(),
    };
    for b in &setup.balls {
        let state = motion::settle(b.state, p);
        sim.balls.push(Live {
            state,
            t_ref: 0.0,
            law_end: motion::duration(&state, p),
            generation: 0,
        });
        sim.tracks.push(Track {
            id: b.id.clone(),
            kind: b.kind,
            segments: vec![Segment { t: 0.0, state }],
        });
    }
    for i in 0..sim.balls.len() {
        sim.schedule_ball(i);
        for j in i + 1..sim.balls.len() {
            sim.schedule_pair(i, j);
        }
    }
    let ending = sim.run()?;
    Ok(Shot {
        params: *p,
        events: sim.events,
        tracks: sim.tracks,
        duration: sim.now,
        ending,
        stats: sim.stats,
    })
}

impl Sim<'_> {
    fn params(&self) -> &Params {
        &self.setup.params
    }

    /// State of ball `i` at the current time.
    fn current(&self, i: usize) -> BallState {
        let b = &self.balls[i];
        motion::state_at(&b.state, self.now - b.t_ref, self.params())
    }

    /// End of the window in which ball `i`'s position follows its current polynomial.
    fn path_end(&self, i: usize) -> f64 {
        let b = &self.balls[i];
        if b.state.motion.is_moving() {
            b.law_end
        } else {
            f64::INFINITY
        }
    }

    /// The latest time up to which candidates are searched.
    fn search_limit(&self) -> f64 {
        self.opts
            .horizon
            .unwrap_or(f64::INFINITY)
            .min(self.opts.max_time)
    }

    fn push(&mut self, t: f64, kind: Candidate, a: usize) {
        self.stats.candidates += 1;
        let gen_b = kind.other_ball().map_or(0, |b| self.balls[b].generation);
        self.queue.push(Entry {
            t,
            kind,
            a,
            gen_a: self.balls[a].generation,
            gen_b,
        });
    }

    /// Schedules the end of ball `i`'s law and its contacts with the table.
    fn schedule_ball(&mut self, i: usize) {
        let st = self.balls[i].state;
        if !st.motion.in_play() {
            return;
        }
        let law_end = self.balls[i].law_end;
        if law_end.is_finite() {
            self.push(law_end, Candidate::Transition, i);
        }
        if !st.motion.is_moving() {
            return;
        }
        let p = *self.params();
        let path = motion::path(&self.current(i), &p);
        let window = law_end.min(self.search_limit()) - self.now;
        let contact = p.cushion_contact_distance();
        let table = &self.setup.table;
        let mut found = Vec::new();
        for (k, c) in table.cushions.iter().enumerate() {
            if let Some(t) = detect::cushion::nose_time(&path, c, contact, window) {
                found.push((t, Candidate::Nose { cushion: k }));
            }
        }
        for (k, j) in table.jaws.iter().enumerate() {
            if let Some(t) = detect::cushion::jaw_time(&path, j, contact, window) {
                found.push((t, Candidate::Jaw { jaw: k }));
            }
        }
        for (k, pk) in table.pockets.iter().enumerate() {
            if let Some(t) = detect::pocket::capture_time(&path, pk, window) {
                found.push((t, Candidate::Pocket { pocket: k }));
            }
        }
        for (t, kind) in found {
            self.push(self.now + t, kind, i);
        }
    }

    /// Schedules the next contact of balls `i` and `j`, if any within both laws' window.
    fn schedule_pair(&mut self, i: usize, j: usize) {
        let (si, sj) = (&self.balls[i].state, &self.balls[j].state);
        if !si.motion.in_play() || !sj.motion.in_play() {
            return;
        }
        if !si.motion.is_moving() && !sj.motion.is_moving() {
            return;
        }
        let end = self
            .path_end(i)
            .min(self.path_end(j))
            .min(self.search_limit());
        let window = end - self.now;
        let (a, b) = (self.current(i), self.current(j));
        if let Some(t) = detect::ball_ball::contact_time(&a, &b, window, self.params()) {
            self.push(self.now + t, Candidate::BallBall { other: j }, i);
        }
    }

    fn is_stale(&self, e: &Entry) -> bool {
        self.balls[e.a].generation != e.gen_a
            || e.kind
                .other_ball()
                .is_some_and(|b| self.balls[b].generation != e.gen_b)
    }

    fn run(&mut self) -> Result<Ending, SimError> {
        let mut same_instant = 0usize;
        while let Some(e) = self.queue.pop() {
            if self.is_stale(&e) {
                self.stats.stale += 1;
                continue;
            }
            if let Some(h) = self.opts.horizon.filter(|&h| e.t > h) {
                self.now = h;
                return Ok(Ending::Horizon);
            }
            if e.t > self.opts.max_time {
                return Err(SimError::DidNotStop {
                    max_time: self.opts.max_time,
                });
            }
            if self.stats.events >= self.opts.max_events {
                return Err(SimError::TooManyEvents {
                    limit: self.opts.max_events,
                    t: self.now,
                });
            }
            same_instant = if e.t == self.now { same_instant + 1 } else { 0 };
            if same_instant > self.opts.max_events_at_instant {
                return Err(SimError::Stuck {
                    t: self.now,
                    count: same_instant,
                });
            }
            self.now = self.now.max(e.t);
            self.stats.events += 1;
            self.resolve(&e)?;
        }
        // Nothing left to happen before the horizon (candidates are only searched up to it).
        if let Some(h) = self.opts.horizon
            && self.balls.iter().any(|b| b.state.motion.is_moving())
        {
            self.now = self.now.max(h);
            return Ok(Ending::Horizon);
        }
        // Nothing left to happen: the laws in force never end, so no ball moves.
        if self.balls.iter().any(|b| b.state.motion.is_moving()) {
            return Err(SimError::DidNotStop {
                max_time: self.opts.max_time,
            });
        }
        Ok(Ending::AtRest)
    }

    fn impact_error(&self, balls: &[usize], err: crate::impact::ImpactError) -> SimError {
        SimError::Impact {
            balls: balls.iter().map(|&i| self.tracks[i].id.clone()).collect(),
            t: self.now,
            error: err,
        }
    }

    /// The impact of ball `i` on a cushion nose, jaw or facing whose plan normal (from the
    /// cushion towards the ball) is `normal`: (kind, balls, before, after, feature, normal speed).
    fn cushion_impact(&self, i: usize, normal: Vec3, name: &str) -> Result<Resolved, SimError> {
        let p = *self.params();
        let s = self.current(i);
        let vn = -s.vel.dot(&normal);
        let pe = Params {
            e_cushion: crate::impact::restitution_floor(p.e_cushion_at(vn), vn),
            ..p
        };
        let s2 = self
            .setup
            .models
            .cushion
            .resolve(&s, normal, &pe)
            .map_err(|err| self.impact_error(&[i], err))?;
        Ok((
            EventKind::BallCushion,
            vec![i],
            vec![s],
            vec![motion::settle(s2, &p)],
            Some(name.to_string()),
            Some(vn),
        ))
    }

    fn resolve(&mut self, e: &Entry) -> Result<(), SimError> {
        let p = *self.params();
        let table = &self.setup.table;
        let (kind, involved, before, after, feature, normal_speed) = match e.kind {
            Candidate::BallBall { other } => {
                let (a, b) = (self.current(e.a), self.current(other));
                let n = (b.pos - a.pos).normalize();
                let approach = (a.vel - b.vel).dot(&n);
                let pe = Params {
                    e_ball: crate::impact::restitution_floor(p.e_ball, approach),
                    ..p
                };
                let (a2, b2) = self
                    .setup
                    .models
                    .ball_ball
                    .resolve(&a, &b, &pe)
                    .map_err(|err| self.impact_error(&[e.a, other], err))?;
                (
                    EventKind::BallBall,
                    vec![e.a, other],
                    vec![a, b],
                    vec![motion::settle(a2, &p), motion::settle(b2, &p)],
                    None,
                    Some(approach),
                )
            }
            Candidate::Nose { cushion } => {
                let c = &table.cushions[cushion];
                self.cushion_impact(e.a, c.normal, &c.name)?
            }
            Candidate::Jaw { jaw } => {
                let j = &table.jaws[jaw];
                let d = self.current(e.a).pos - j.centre;
                let normal = crate::ball::Vec3::new(d.x, d.y, 0.0).normalize();
                self.cushion_impact(e.a, normal, &j.name)?
            }
            Candidate::Pocket { pocket } => {
                let s = self.current(e.a);
                let mut s2 = s;
                s2.vel = crate::ball::Vec3::zeros();
                s2.spin = crate::ball::Vec3::zeros();
                s2.motion = Motion::Pocketed;
                (
                    EventKind::BallPocket,
                    vec![e.a],
                    vec![s],
                    vec![s2],
                    Some(table.pockets[pocket].name.clone()),
                    None,
                )
            }
            Candidate::Transition => {
                let s = self.current(e.a);
                let Some((t, s2)) = motion::finish(&self.balls[e.a].state, &s, &p) else {
                    return Ok(());
                };
                (
                    EventKind::Transition(t),
                    vec![e.a],
                    vec![s],
                    vec![s2],
                    None,
                    None,
                )
            }
        };
        for (&i, s) in involved.iter().zip(&after) {
            if !s.is_finite() {
                return Err(SimError::NonFinite {
                    ball: self.tracks[i].id.clone(),
                    t: self.now,
                });
            }
            let b = &mut self.balls[i];
            b.state = *s;
            b.t_ref = self.now;
            b.law_end = self.now + motion::duration(s, &p);
            b.generation += 1;
            self.tracks[i].segments.push(Segment {
                t: self.now,
                state: *s,
            });
        }
        for &i in &involved {
            self.schedule_ball(i);
            for j in 0..self.balls.len() {
                // Each pair once: skip pairs of two involved balls unless i is the first of them.
                if j == i || (involved.contains(&j) && j < i) {
                    continue;
                }
                self.schedule_pair(i, j);
            }
        }
        if kind == EventKind::Transition(motion::Transition::Refresh) {
            // A renewal of a law's accelerations, not a physical event: the track keeps the
            // segment, the event list does not.
            self.stats.refreshes += 1;
            return Ok(());
        }
        self.events.push(Event {
            t: self.now,
            kind,
            balls: involved,
            after,
            before,
            feature,
            normal_speed,
        });
        Ok(())
    }
}
