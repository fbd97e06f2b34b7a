//! The event loop, and a ball's orientation along its track ([`orientation`]).
//!
//! Each ball is kept as a state at its own reference time plus the law it follows, and is
//! evaluated on demand; an event only advances the balls it touches. After an event on balls S
//! their generations are bumped and only their candidates are recomputed: the end of their
//! law, their cushion, jaw and pocket contacts, and their contacts with every other ball, each
//! searched only within the window where both laws hold. Stale candidates are dropped when
//! popped.

pub mod error;
pub mod event;
pub mod orientation;
pub(crate) mod queue;
pub mod setup;
pub mod shot;

use crate::ball::{BallState, Motion, Vec3};
use crate::detect::{self, bounds::PlanBox, cushion, cushion::NoseEdge};
use crate::impact::{CushionContact, GRAZING_APPROACH, separation};
use crate::motion;
use crate::params::Params;
use crate::table::{Cushion, Jaw, Table};
pub use error::SimError;
pub use event::{Event, EventKind};
use queue::{Candidate, Entry, Queue};
pub use setup::{Setup, SetupError, SimOptions};
pub use shot::{Ending, Segment, Shot, Stats, Track};

/// A cushion's nose edge a ball touches: a straight nose (or facing), or a jaw's arc.
#[derive(Clone, Copy)]
enum NoseLine<'a> {
    Straight(&'a Cushion),
    Jaw(&'a Jaw),
}

/// What resolving a candidate gave: the event, before its states are installed.
struct Resolved {
    kind: EventKind,
    /// The balls involved.
    balls: Vec<usize>,
    /// Their states just before and just after.
    before: Vec<BallState>,
    after: Vec<BallState>,
    /// The cushion, jaw or pocket involved, by name.
    feature: Option<String>,
    /// For impacts: the approach speed along the contact normal, m/s.
    normal_speed: Option<f64>,
}

struct Live {
    /// State at `t_ref`.
    state: BallState,
    t_ref: f64,
    /// Absolute time at which the current law ends.
    law_end: f64,
    /// Half the acceleration of the law since `t_ref` (see [`Sim::law_path`]).
    half_accel: Vec3,
    generation: u64,
    /// The law path last computed, with the time and generation it was computed for: every
    /// pair scheduled after an event reuses it.
    path_memo: Option<(f64, u64, motion::Path)>,
}

impl Live {
    /// Ball in `state` from `t_ref` on.
    fn new(state: BallState, t_ref: f64, generation: u64, p: &Params) -> Live {
        let (duration, path) = motion::duration_and_path(&state, p);
        Live {
            state,
            t_ref,
            law_end: t_ref + duration,
            half_accel: path.a,
            generation,
            path_memo: None,
        }
    }
}

struct Sim<'a> {
    setup: &'a Setup,
    /// The table's quiet middle ([`quiet_box`]).
    quiet: Option<PlanBox>,
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
    opts.validate().map_err(SimError::Setup)?;
    let p = &setup.params;
    let mut sim = Sim {
        setup,
        quiet: quiet_box(&setup.table, p),
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
        sim.balls.push(Live::new(state, 0.0, 0, p));
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

/// A box of the table's middle that none of [`Sim::schedule_ball`]'s tests for the cushions,
/// jaws and pockets sees, on the cloth or in the air: a ball whose reach lies within it is
/// searched against none of them (each test is monotone, [`PlanBox::contains`], so this skips
/// only searches that would find nothing: results are the same bits). The table's box of noses,
/// inset until no test sees it; `None` without cushions or if no inset does.
fn quiet_box(table: &Table, p: &Params) -> Option<PlanBox> {
    let first = table.cushions.first()?;
    let (mut lo, mut hi) = (
        [first.start.x, first.start.y],
        [first.start.x, first.start.y],
    );
    for c in &table.cushions {
        for q in [c.start, c.end] {
            lo = [lo[0].min(q.x), lo[1].min(q.y)];
            hi = [hi[0].max(q.x), hi[1].max(q.y)];
        }
    }
    // The margins of schedule_ball's tests: on the cloth and in the air.
    let margins = [p.cushion_contact_distance(), p.ball_radius];
    let sees = |b: &PlanBox| {
        margins.iter().any(|&m| {
            table
                .cushions
                .iter()
                .any(|c| b.near_segment(c.start, c.end, m))
                || table
                    .jaws
                    .iter()
                    .any(|j| b.near_point(j.centre, j.radius + m))
        }) || table
            .pockets
            .iter()
            .any(|pk| b.near_point(pk.centre, pk.radius) || b.near_point(pk.mouth, pk.back_reach()))
    };
    let mut inset = 2.0 * p.ball_radius;
    for _ in 0..12 {
        let b = PlanBox::new(
            [lo[0] + inset, lo[1] + inset],
            [hi[0] - inset, hi[1] - inset],
        );
        if b.lo_below_hi() && !sees(&b) {
            return Some(b);
        }
        inset *= 1.25;
    }
    None
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

    /// Ball `i`'s path from now: its current position and velocity, and the acceleration its
    /// law has held since the law began (with the cloth's effects on, a law holds the
    /// acceleration of its segment's start, which the current state would not reproduce).
    /// Computed once per ball and instant.
    fn law_path(&mut self, i: usize) -> motion::Path {
        let b = &self.balls[i];
        if let Some((t, generation, path)) = b.path_memo
            && t == self.now
            && generation == b.generation
        {
            return path;
        }
        let now = self.current(i);
        let path = motion::Path {
            c: now.pos,
            b: if now.motion.is_moving() {
                now.vel
            } else {
                Vec3::zeros()
            },
            a: b.half_accel,
        };
        let b = &mut self.balls[i];
        b.path_memo = Some((self.now, b.generation, path));
        path
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
        let path = self.law_path(i);
        let window = law_end.min(self.search_limit()) - self.now;
        // The table outlives the borrow of `self`: candidates are pushed as they are met.
        let setup = self.setup;
        let table = &setup.table;
        // Where the ball can be before its law ends: features clearly away from it are not
        // searched.
        let reach = PlanBox::of(&path, window);
        if self.quiet.is_some_and(|q| q.contains(&reach)) {
            return;
        }
        if st.motion == Motion::Airborne {
            // In the air the nose is an edge at its height: met anywhere on the ball, or
            // cleared (thesis §6.2's geometry, off the cloth).
            let edge = NoseEdge {
                height: p.cushion_height,
                radius: p.ball_radius,
            };
            for (k, c) in table.cushions.iter().enumerate() {
                // Both need the centre within R of the nose line in plan.
                if !reach.near_segment(c.start, c.end, edge.radius) {
                    continue;
                }
                if let Some(t) = cushion::nose_time_in_air(&path, c, edge, window) {
                    self.push(self.now + t, Candidate::Nose { cushion: k }, i);
                }
                if let Some(t) = cushion::over_time(&path, c, edge, window) {
                    self.push(self.now + t, Candidate::OverCushion { cushion: k }, i);
                }
            }
            for (k, j) in table.jaws.iter().enumerate() {
                if !reach.near_point(j.centre, j.radius + edge.radius) {
                    continue;
                }
                if let Some(t) = cushion::jaw_time_in_air(&path, j, edge, window) {
                    self.push(self.now + t, Candidate::Jaw { jaw: k }, i);
                }
                if let Some(t) = cushion::over_jaw_time(&path, j, edge, window) {
                    self.push(self.now + t, Candidate::OverJaw { jaw: k }, i);
                }
            }
            // Over a pocket's opening: drops in, or clears the pocket's back
            // (detect/pocket.rs).
            for (k, pk) in table.pockets.iter().enumerate() {
                if !reach.near_point(pk.mouth, pk.back_reach()) {
                    continue;
                }
                let over_fall = reach.near_point(pk.centre, pk.radius);
                if over_fall
                    && let Some(t) = detect::pocket::drop_time_in_air(&path, pk, edge, window)
                {
                    self.push(self.now + t, Candidate::Pocket { pocket: k }, i);
                }
                let far_edge = over_fall
                    .then(|| detect::pocket::far_edge_time(&path, pk, edge, window))
                    .flatten();
                let back = detect::pocket::back_time(&path, pk, window)
                    .map(|t| (t, edge.cleared_at(path.at(t).z)));
                for (t, clears) in far_edge.into_iter().chain(back) {
                    let kind = if clears {
                        Candidate::OverPocket { pocket: k }
                    } else {
                        Candidate::Pocket { pocket: k }
                    };
                    self.push(self.now + t, kind, i);
                }
            }
        } else {
            let contact = p.cushion_contact_distance();
            for (k, c) in table.cushions.iter().enumerate() {
                if reach.near_segment(c.start, c.end, contact)
                    && let Some(t) = cushion::nose_time(&path, c, contact, window)
                {
                    self.push(self.now + t, Candidate::Nose { cushion: k }, i);
                }
            }
            for (k, j) in table.jaws.iter().enumerate() {
                if reach.near_point(j.centre, j.radius + contact)
                    && let Some(t) = cushion::jaw_time(&path, j, contact, window)
                {
                    self.push(self.now + t, Candidate::Jaw { jaw: k }, i);
                }
            }
            for (k, pk) in table.pockets.iter().enumerate() {
                if reach.near_point(pk.centre, pk.radius)
                    && let Some(t) = detect::pocket::capture_time(&path, pk, window)
                {
                    self.push(self.now + t, Candidate::Pocket { pocket: k }, i);
                }
                // Beside a deep pocket's fall, its back (detect/pocket.rs).
                if reach.near_point(pk.mouth, pk.back_reach())
                    && let Some(t) = detect::pocket::back_time(&path, pk, window)
                {
                    self.push(self.now + t, Candidate::Pocket { pocket: k }, i);
                }
            }
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
        let (a, b) = (self.law_path(i), self.law_path(j));
        let radius = self.params().ball_radius;
        if let Some(t) = detect::ball_ball::contact_time(&a, &b, window, radius) {
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
        let at_instant = self.opts.events_at_instant_cap(self.balls.len());
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
            if same_instant > at_instant {
                return Err(SimError::Stuck {
                    t: self.now,
                    count: same_instant,
                });
            }
            self.now = self.now.max(e.t);
            self.resolve(&e)?;
        }
        // Nothing left to happen before the horizon (candidates are only searched up to it).
        if let Some(h) = self.opts.horizon
            && self.balls.iter().any(|b| !b.state.motion.has_stopped())
        {
            self.now = self.now.max(h);
            return Ok(Ending::Horizon);
        }
        // Nothing left to happen: a ball not yet stopped is under a law that never ends
        // (a spin that never decays, with sidespin_decel = 0): the shot did not stop.
        if self.balls.iter().any(|b| !b.state.motion.has_stopped()) {
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

    /// The impact of ball `i` on a cushion nose, jaw or facing named `name`, touching at
    /// `contact`; the ball leaves separating at [`MIN_SEPARATION`] at least.
    fn cushion_impact(
        &self,
        i: usize,
        contact: CushionContact,
        name: &str,
    ) -> Result<Resolved, SimError> {
        let p = *self.params();
        let s = self.current(i);
        let vn = contact.approach(&s);
        let pe = Params {
            e_cushion: p.e_cushion_at(vn),
            ..p
        };
        let mut s2 = if vn < GRAZING_APPROACH {
            s
        } else {
            self.setup
                .models
                .cushion
                .resolve(&s, contact, &pe)
                .map_err(|err| self.impact_error(&[i], err))?
        };
        let away = match contact {
            CushionContact::OnCloth { normal } => normal,
            CushionContact::InAir { towards } => -towards,
        };
        separation::separate_from_fixed(&mut s2, away);
        Ok(Resolved {
            kind: EventKind::BallCushion,
            balls: vec![i],
            before: vec![s],
            after: vec![motion::settle(s2, &p)],
            feature: Some(name.to_string()),
            normal_speed: Some(vn),
        })
    }

    /// Where ball `i`, now touching the nose `edge`, touches it.
    fn cushion_contact(&self, i: usize, edge: NoseLine) -> CushionContact {
        let s = self.current(i);
        let p = self.params();
        let plan = |v: Vec3| Vec3::new(v.x, v.y, 0.0);
        // The plan normal from the cushion towards the ball, and the nearest point of the
        // nose edge in plan.
        let (normal, edge) = match edge {
            NoseLine::Straight(c) => {
                let d = c.normal.dot(&plan(s.pos - c.start));
                (c.normal, plan(s.pos) - d * c.normal)
            }
            NoseLine::Jaw(j) => {
                // A ball right above the jaw's axis meets it on the side it comes from.
                let d = plan(s.pos - j.centre);
                let n = d
                    .try_normalize(0.0)
                    .or_else(|| (-plan(s.vel)).try_normalize(0.0))
                    .unwrap_or_else(Vec3::x);
                (n, plan(j.centre) + j.radius * n)
            }
        };
        if s.motion == Motion::Airborne {
            let point = edge + Vec3::new(0.0, 0.0, p.cushion_height);
            let towards = (point - s.pos).try_normalize(0.0).unwrap_or(-normal);
            CushionContact::InAir { towards }
        } else {
            CushionContact::OnCloth { normal }
        }
    }

    /// Ball `i` leaves play (into a pocket, or off the table over a cushion) where it is now.
    fn out_of_play(&self, i: usize, motion: Motion, feature: &str) -> Resolved {
        let s = self.current(i);
        let gone = BallState {
            vel: Vec3::zeros(),
            spin: Vec3::zeros(),
            motion,
            ..s
        };
        Resolved {
            kind: if motion == Motion::Pocketed {
                EventKind::BallPocket
            } else {
                EventKind::BallOffTable
            },
            balls: vec![i],
            before: vec![s],
            after: vec![gone],
            feature: Some(feature.to_string()),
            normal_speed: None,
        }
    }

    fn resolve(&mut self, e: &Entry) -> Result<(), SimError> {
        let p = *self.params();
        let table = &self.setup.table;
        let resolved = match e.kind {
            Candidate::BallBall { other } => {
                let (a, b) = (self.current(e.a), self.current(other));
                let n = (b.pos - a.pos).normalize();
                let approach = (a.vel - b.vel).dot(&n);
                let (mut a2, mut b2) = if approach < GRAZING_APPROACH {
                    (a, b)
                } else {
                    self.setup
                        .models
                        .ball_ball
                        .resolve(&a, &b, &p)
                        .map_err(|err| self.impact_error(&[e.a, other], err))?
                };
                separation::separate_balls(&mut a2, &mut b2, n);
                if approach <= separation::RESTING_APPROACH {
                    separation::stay_on_cloth(&mut a2, &a, &p);
                    separation::stay_on_cloth(&mut b2, &b, &p);
                }
                Resolved {
                    kind: EventKind::BallBall,
                    balls: vec![e.a, other],
                    before: vec![a, b],
                    after: vec![motion::settle(a2, &p), motion::settle(b2, &p)],
                    feature: None,
                    normal_speed: Some(approach),
                }
            }
            Candidate::Nose { cushion } => {
                let c = &table.cushions[cushion];
                let contact = self.cushion_contact(e.a, NoseLine::Straight(c));
                self.cushion_impact(e.a, contact, &c.name)?
            }
            Candidate::Jaw { jaw } => {
                let j = &table.jaws[jaw];
                let contact = self.cushion_contact(e.a, NoseLine::Jaw(j));
                self.cushion_impact(e.a, contact, &j.name)?
            }
            Candidate::Pocket { pocket } => {
                self.out_of_play(e.a, Motion::Pocketed, &table.pockets[pocket].name)
            }
            Candidate::OverCushion { cushion } => {
                self.out_of_play(e.a, Motion::OffTable, &table.cushions[cushion].name)
            }
            Candidate::OverJaw { jaw } => {
                self.out_of_play(e.a, Motion::OffTable, &table.jaws[jaw].name)
            }
            Candidate::OverPocket { pocket } => {
                let back = format!("{}/back", table.pockets[pocket].name);
                self.out_of_play(e.a, Motion::OffTable, &back)
            }
            Candidate::Transition => {
                let s = self.current(e.a);
                let Some((t, s2)) = motion::finish(&self.balls[e.a].state, &s, &p) else {
                    return Ok(());
                };
                Resolved {
                    kind: EventKind::Transition(t),
                    balls: vec![e.a],
                    before: vec![s],
                    after: vec![s2],
                    feature: None,
                    normal_speed: None,
                }
            }
        };
        let Resolved {
            kind,
            balls: involved,
            before,
            after,
            feature,
            normal_speed,
        } = resolved;
        for (&i, s) in involved.iter().zip(&after) {
            if !s.is_finite() {
                return Err(SimError::NonFinite {
                    ball: self.tracks[i].id.clone(),
                    t: self.now,
                });
            }
            let b = &mut self.balls[i];
            *b = Live::new(*s, self.now, b.generation + 1, &p);
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
            // segment, the event list and the event count do not.
            self.stats.refreshes += 1;
            return Ok(());
        }
        // Balls this event sends off the cloth: from the cloth into the air, or off the bed
        // again at a landing that bounces (`e_bed`; the thesis's landing stays down, §6.1.6).
        let bounce = kind == EventKind::Transition(motion::Transition::Landing);
        let lifted: Vec<(usize, BallState)> = involved
            .iter()
            .zip(before.iter().zip(&after))
            .filter(|(_, (b, a))| {
                a.motion == Motion::Airborne && (bounce || b.motion != Motion::Airborne)
            })
            .map(|(&i, (_, a))| (i, *a))
            .collect();
        self.stats.events += 1;
        self.events.push(Event {
            t: self.now,
            kind,
            balls: involved,
            after,
            before,
            feature,
            normal_speed,
        });
        for (i, s) in lifted {
            self.stats.lift_offs += 1;
            self.events.push(Event {
                t: self.now,
                kind: EventKind::LiftOff,
                balls: vec![i],
                after: vec![s],
                before: vec![s],
                feature: None,
                normal_speed: None,
            });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::SnookerDims;

    #[test]
    fn the_quiet_middle_covers_most_of_the_snooker_bed_and_no_test_sees_it() {
        let p = Params::default();
        let table = Table::snooker(&SnookerDims::default());
        let q = quiet_box(&table, &p).expect("a quiet middle");
        // Most of the 3.569 x 1.778 m bed: searches are skipped there.
        let inner = PlanBox::new([0.4, 0.35], [3.17, 1.43]);
        assert!(q.contains(&inner), "{q:?}");
        // Nothing of the table is within it: each test of schedule_ball is false.
        let m = p.cushion_contact_distance().max(p.ball_radius);
        for c in &table.cushions {
            assert!(!q.near_segment(c.start, c.end, m), "{}", c.name);
        }
        for j in &table.jaws {
            assert!(!q.near_point(j.centre, j.radius + m), "{}", j.name);
        }
        for pk in &table.pockets {
            assert!(!q.near_point(pk.mouth, pk.back_reach()), "{}", pk.name);
            assert!(!q.near_point(pk.centre, pk.radius), "{}", pk.name);
        }
        // The open table has no features: nothing to skip.
        assert!(quiet_box(&Table::open(), &p).is_none());
    }
}
