//! The event loop.
//!
//! Each ball is kept as a state at its own reference time plus the law it follows, and is
//! evaluated on demand; an event only advances the balls it touches. After an event on balls S
//! their generations are bumped and only their candidates are recomputed: the end of their
//! law, their cushion, jaw and pocket contacts, and their contacts with every other ball, each
//! searched only within the window where both laws hold. Stale candidates are dropped when
//! popped.

pub mod event;
pub mod queue;
pub mod shot;

use crate::ball::{Ball, BallState, Motion};
use crate::detect;
use crate::impact::Models;
use crate::motion;
use crate::params::Params;
use crate::table::Table;
pub use event::{Event, EventKind};
use queue::{Candidate, Entry, Queue};
use serde::{Deserialize, Serialize};
pub use shot::{Ending, Segment, Shot, Stats, Track};

/// Limits of one simulation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SimOptions {
    /// Most events a shot may have before it is stopped with an error.
    pub max_events: usize,
    /// Most events at one and the same instant before the shot is stopped with an error.
    pub max_events_at_instant: usize,
    /// Simulated time within which every ball must come to rest, s.
    pub max_time: f64,
    /// Stop (without error) at this time even if balls still move.
    pub horizon: Option<f64>,
}

impl Default for SimOptions {
    fn default() -> Self {
        SimOptions {
            max_events: 100_000,
            max_events_at_instant: 10_000,
            max_time: 3600.0,
            horizon: None,
        }
    }
}

/// Everything a shot starts from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Setup {
    /// The table.
    pub table: Table,
    /// Physical parameters.
    pub params: Params,
    /// Impact models.
    pub models: Models,
    /// The balls with their starting states.
    pub balls: Vec<Ball>,
}

/// A setup that cannot be simulated.
#[derive(Clone, Debug, PartialEq)]
pub struct SetupError {
    /// Index of the ball at fault, if one is.
    pub ball: Option<usize>,
    /// The field at fault ("pos", "vel", "spin", "id", or a parameter name).
    pub field: String,
    /// Why.
    pub reason: String,
}

impl std::fmt::Display for SetupError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.ball {
            Some(i) => write!(f, "balls[{i}].{}: {}", self.field, self.reason),
            None => write!(f, "{}: {}", self.field, self.reason),
        }
    }
}

impl std::error::Error for SetupError {}

/// Why a simulation stopped without finishing the shot.
#[derive(Clone, Debug, PartialEq)]
pub enum SimError {
    /// The setup is invalid.
    Setup(SetupError),
    /// More than `max_events` events.
    TooManyEvents {
        /// The limit.
        limit: usize,
        /// Time reached, s.
        t: f64,
    },
    /// More than `max_events_at_instant` events without time advancing.
    Stuck {
        /// The instant, s.
        t: f64,
        /// Events at that instant.
        count: usize,
    },
    /// Balls still moving after `max_time`.
    DidNotStop {
        /// The limit, s.
        max_time: f64,
    },
    /// An impact model failed to converge (a bug: reported rather than passed on).
    Impact {
        /// Balls involved.
        balls: Vec<String>,
        /// Time, s.
        t: f64,
        /// What failed.
        error: crate::impact::ImpactError,
    },
    /// A non-finite number appeared (a bug: reported rather than passed on).
    NonFinite {
        /// Ball id.
        ball: String,
        /// Time, s.
        t: f64,
    },
}

impl std::fmt::Display for SimError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SimError::Setup(e) => write!(f, "{e}"),
            SimError::TooManyEvents { limit, t } => write!(
                f,
                "the shot exceeded {limit} events (at t = {t:.6} s); stopped as a runaway"
            ),
            SimError::Stuck { t, count } => write!(
                f,
                "{count} events at the same instant t = {t:.9} s without time advancing; stopped"
            ),
            SimError::DidNotStop { max_time } => write!(
                f,
                "balls were still moving after {max_time} s of simulated time \
                 (is there no rolling resistance or sliding friction?)"
            ),
            SimError::Impact { balls, t, error } => write!(
                f,
                "internal error: the impact of {} at t = {t} s failed: {}",
                balls.join(" and "),
                error.reason()
            ),
            SimError::NonFinite { ball, t } => write!(
                f,
                "internal error: a non-finite value appeared for ball {ball} at t = {t} s"
            ),
        }
    }
}

impl std::error::Error for SimError {}

impl Setup {
    /// Checks parameters and the starting positions: finite numbers, unique ids, every ball on
    /// the cloth and clear of the cushions, no two balls overlapping (touching is allowed).
    pub fn validate(&self) -> Result<(), SetupError> {
        self.params.validate().map_err(|e| SetupError {
            ball: None,
            field: format!("params.{}", e.name),
            reason: e.reason,
        })?;
        let p = &self.params;
        let r = p.ball_radius;
        let contact = p.cushion_contact_distance();
        for (i, b) in self.balls.iter().enumerate() {
            let bad = |field: &str, reason: String| SetupError {
                ball: Some(i),
                field: field.into(),
                reason,
            };
            for (field, v) in [
                ("pos", b.state.pos),
                ("vel", b.state.vel),
                ("spin", b.state.spin),
            ] {
                if !v.iter().all(|x| x.is_finite()) {
                    return Err(bad(
                        field,
                        format!("ball \"{}\": values must be finite", b.id),
                    ));
                }
            }
            if self.balls[..i].iter().any(|o| o.id == b.id) {
                return Err(bad("id", format!("ball id \"{}\" is used twice", b.id)));
            }
            if b.state.pos.z < r - detect::TOUCH_TOL {
                return Err(bad("pos", format!("ball \"{}\" is below the cloth", b.id)));
            }
            if b.state.pos.z <= r + motion::ON_CLOTH && b.state.vel.z < 0.0 {
                return Err(bad(
                    "vel",
                    format!("ball \"{}\" is on the cloth and moving down into it", b.id),
                ));
            }
            if let Some(why) = self
                .table
                .placement_error(b.state.pos.xy().push(0.0), contact)
            {
                return Err(bad("pos", format!("ball \"{}\": {why}", b.id)));
            }
            for o in &self.balls[..i] {
                let gap = (b.state.pos - o.state.pos).norm() - 2.0 * r;
                if gap < -detect::TOUCH_TOL {
                    return Err(bad(
                        "pos",
                        format!(
                            "ball \"{}\" overlaps ball \"{}\" by {:.3} mm",
                            b.id,
                            o.id,
                            -gap * 1e3
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}

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

    fn push(&mut self, t: f64, kind: Candidate, a: usize, b: usize, feature: usize) {
        self.stats.candidates += 1;
        let gen_b = if b == usize::MAX {
            0
        } else {
            self.balls[b].generation
        };
        self.queue.push(Entry {
            t,
            kind,
            a,
            b,
            feature,
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
            self.push(law_end, Candidate::Transition, i, usize::MAX, 0);
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
                found.push((t, Candidate::Nose, k));
            }
        }
        for (k, j) in table.jaws.iter().enumerate() {
            if let Some(t) = detect::cushion::jaw_time(&path, j, contact, window) {
                found.push((t, Candidate::Jaw, k));
            }
        }
        for (k, pk) in table.pockets.iter().enumerate() {
            if let Some(t) = detect::pocket::capture_time(&path, pk, window) {
                found.push((t, Candidate::Pocket, k));
            }
        }
        for (t, kind, k) in found {
            self.push(self.now + t, kind, i, usize::MAX, k);
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
            self.push(self.now + t, Candidate::BallBall, i, j, 0);
        }
    }

    fn is_stale(&self, e: &Entry) -> bool {
        self.balls[e.a].generation != e.gen_a
            || (e.b != usize::MAX && self.balls[e.b].generation != e.gen_b)
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

    fn resolve(&mut self, e: &Entry) -> Result<(), SimError> {
        let p = *self.params();
        let table = &self.setup.table;
        let (kind, involved, before, after, feature, normal_speed) = match e.kind {
            Candidate::BallBall => {
                let (a, b) = (self.current(e.a), self.current(e.b));
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
                    .map_err(|err| self.impact_error(&[e.a, e.b], err))?;
                (
                    EventKind::BallBall,
                    vec![e.a, e.b],
                    vec![a, b],
                    vec![motion::settle(a2, &p), motion::settle(b2, &p)],
                    None,
                    Some(approach),
                )
            }
            Candidate::Nose | Candidate::Jaw => {
                let s = self.current(e.a);
                let (normal, name) = if e.kind == Candidate::Nose {
                    let c = &table.cushions[e.feature];
                    (c.normal, c.name.clone())
                } else {
                    let j = &table.jaws[e.feature];
                    let d = s.pos - j.centre;
                    (
                        crate::ball::Vec3::new(d.x, d.y, 0.0).normalize(),
                        j.name.clone(),
                    )
                };
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
                    .map_err(|err| self.impact_error(&[e.a], err))?;
                (
                    EventKind::BallCushion,
                    vec![e.a],
                    vec![s],
                    vec![motion::settle(s2, &p)],
                    Some(name),
                    Some(vn),
                )
            }
            Candidate::Pocket => {
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
                    Some(table.pockets[e.feature].name.clone()),
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
