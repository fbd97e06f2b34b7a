//! Invariants of a simulated shot, checked from outside the event loop: events in time order,
//! every state finite, no two balls in play overlapping by more than [`MAX_OVERLAP`] at any
//! event or any sampled instant, energy never rising between events and rising at an event by
//! no more than that event's allowance ([`event_allowance`]), every ball in play on the
//! table, and every ball at rest or out of play at the end. The tests, the fuzz harness and
//! anyone embedding the engine can run them on any shot: [`events`] at the events alone
//! (cheap), [`audit`] also on a fine grid of instants.

use crate::ball::{BallState, Motion};
use crate::detect::{SKIN, TOUCH_TOL, VERIFY_TOL};
use crate::impact::impulse::TOLERANCE;
use crate::impact::separation::{MIN_SEPARATION, RESTING_APPROACH};
use crate::motion::Transition;
use crate::motion::cloth::SEGMENT;
use crate::params::Params;
use crate::sim::{Ending, Event, EventKind, Setup, Shot};
use crate::table::Table;
use std::cmp::Ordering;

/// Largest overlap of two balls in play the engine promises at any instant, m (1 µm).
pub const MAX_OVERLAP: f64 = 1e-6;
/// Sampling interval of [`audit`]'s sweep, s.
pub const SAMPLE_INTERVAL: f64 = 5e-4;

/// What a sweep of a shot found.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Sweep {
    /// Largest overlap of two balls in play, m.
    pub max_overlap: f64,
    /// Where it happened: time and the two ids.
    pub worst: Option<(f64, String, String)>,
    /// First time a ball in play was off the table, with its id and plan position.
    pub escaped: Option<(f64, String, [f64; 2])>,
    /// First time a state was not finite, with the ball's id.
    pub non_finite: Option<(f64, String)>,
    /// Samples taken.
    pub samples: usize,
}

/// Slack of the position checks beyond the contact distances, m.
pub const POSITION_TOL: f64 = 1e-6;

/// Whether ball state `s` (in play) is where a ball in play can be: its centre on the playing
/// area or in a pocket's opening ([`Table::holds`]), sunk into no nose edge by more than
/// [`POSITION_TOL`] — at least R cos theta from a nose line on the cloth, R from the edge in
/// the air, up to the nose line itself for a ball whose lowest point is above the nose (one
/// that crosses the line leaves play by its own event, `ball_off_table`). The depth, not the
/// plan distance, is what the tolerance bounds: for a ball resting on top of the edge the plan
/// distance at which it touches changes without bound with its height.
pub fn on_table(table: &Table, p: &Params, s: &BallState) -> bool {
    let r = p.ball_radius - POSITION_TOL;
    let rise = p.cushion_height - s.pos.z;
    let reach = if rise.abs() < r {
        (r * r - rise * rise).sqrt()
    } else {
        0.0
    };
    table.holds(s.pos, reach, POSITION_TOL)
}

/// Every ball in play that is not on the table ([`on_table`]) just after an event or at the
/// end of `shot` (played on `table`): a ball that left the cloth without an event. Cheap (the
/// states at the events only); [`audit`] also samples between them.
pub fn positions(table: &Table, shot: &Shot) -> Vec<Violation> {
    let p = &shot.params;
    let mut out = Vec::new();
    for e in &shot.events {
        for (&b, s) in e.balls.iter().zip(&e.after) {
            if s.motion.in_play() && s.is_finite() && !on_table(table, p, s) {
                out.push(Violation::OffTable {
                    t: e.t,
                    ball: shot.tracks[b].id.clone(),
                    pos: [s.pos.x, s.pos.y],
                });
            }
        }
    }
    for (tr, s) in shot.tracks.iter().zip(shot.final_states()) {
        if s.motion.in_play() && s.is_finite() && !on_table(table, p, &s) {
            out.push(Violation::OffTable {
                t: shot.duration,
                ball: tr.id.clone(),
                pos: [s.pos.x, s.pos.y],
            });
        }
    }
    out
}

/// Samples every ball of `shot` every `dt` seconds and just before and after every event,
/// measuring pairwise overlap and checking that balls in play stay on the table.
///
/// At most 10^7 steps: a smaller `dt` (zero, negative or NaN included) is taken as the
/// duration over 10^7 (a zero `dt` asked for an endless list of times).
pub fn sweep(setup: &Setup, shot: &Shot, dt: f64) -> Sweep {
    let p = &shot.params;
    let r = p.ball_radius;
    let mut times: Vec<f64> = Vec::new();
    let dt = dt.max(shot.duration / 1e7);
    let n = if dt > 0.0 {
        (shot.duration / dt).ceil() as usize
    } else {
        0
    };
    times.extend((0..=n).map(|k| (k as f64 * dt).min(shot.duration)));
    for e in &shot.events {
        for d in [-1e-7, -1e-9, 0.0, 1e-9, 1e-7] {
            let t = e.t + d;
            if t >= 0.0 && t <= shot.duration {
                times.push(t);
            }
        }
    }
    let mut out = Sweep::default();
    for &t in &times {
        let states: Vec<_> = shot.tracks.iter().map(|tr| tr.state_at(t, p)).collect();
        out.samples += 1;
        for (i, a) in states.iter().enumerate() {
            if !a.motion.in_play() {
                continue;
            }
            if out.non_finite.is_none() && !a.is_finite() {
                out.non_finite = Some((t, shot.tracks[i].id.clone()));
            }
            if out.escaped.is_none() && !on_table(&setup.table, p, a) {
                out.escaped = Some((t, shot.tracks[i].id.clone(), [a.pos.x, a.pos.y]));
            }
            for (j, b) in states.iter().enumerate().skip(i + 1) {
                if !b.motion.in_play() {
                    continue;
                }
                let overlap = 2.0 * r - (a.pos - b.pos).norm();
                if overlap > out.max_overlap {
                    out.max_overlap = overlap;
                    out.worst = Some((t, shot.tracks[i].id.clone(), shot.tracks[j].id.clone()));
                }
            }
        }
    }
    out
}

/// Mechanical energy of the balls `states`, J: kinetic (translation and rotation) while in
/// play, potential above the cloth, and potential along a tilted bed (which the balls' rolling
/// downhill turns into kinetic energy). A ball out of play keeps the potential energy of where
/// it left play, so that leaving play never counts as a gain.
pub fn energy(states: &[BallState], p: &Params) -> f64 {
    let inertia = p.inertia();
    states
        .iter()
        .map(|s| {
            let kinetic = if s.motion.in_play() {
                0.5 * p.ball_mass * s.vel.norm_squared() + 0.5 * inertia * s.spin.norm_squared()
            } else {
                0.0
            };
            let height = (s.pos.z - p.ball_radius).max(0.0);
            let bed = p.slope_x * s.pos.x + p.slope_y * s.pos.y;
            kinetic + p.ball_mass * p.g * (height - bed)
        })
        .sum()
}

/// The most energy the motion between two events `dt` apart may add to `balls` balls, J:
/// nothing, but for the nap's held acceleration ([`crate::motion::cloth`]). The nap pushes
/// sideways and so does no work, but the laws hold its direction over segments of at most
/// [`SEGMENT`] s: over a segment of length tau its work is at most 1/2 M |nap| |a| tau^2,
/// with |a| <= |nap| + g |slope| + mu_slide g the largest acceleration on the cloth; summed
/// over segments, at most 1/2 M |nap| |a| SEGMENT dt per ball.
pub fn motion_allowance(p: &Params, balls: usize, dt: f64) -> f64 {
    if p.nap_drift == 0.0 {
        return 0.0;
    }
    let a = p.nap_drift.abs() + p.g * p.tilt() + p.mu_slide.max(p.mu_slide_low) * p.g;
    balls as f64 * 0.5 * p.ball_mass * p.nap_drift.abs() * a * SEGMENT * (dt + SEGMENT)
}

/// The most energy the separation push of an event of kind `kind` may add, J. An impact that
/// leaves the bodies separating slower than [`MIN_SEPARATION`] is pushed to that speed (the
/// micro-collisions of a sustained contact, [`crate::impact::separation`]), which adds at most
/// 1/2 m_eff MIN_SEPARATION^2: m_eff = M/2 for two equal balls, M for a ball against a cushion
/// (with the ball's mass M of the scene: 3.5e-8 J and 7.0e-8 J at the thesis's 0.1406 kg).
/// No other event adds energy.
pub fn energy_allowance(kind: EventKind, p: &Params) -> f64 {
    let m_eff = match kind {
        EventKind::BallBall => p.ball_mass / 2.0,
        EventKind::BallCushion => p.ball_mass,
        _ => 0.0,
    };
    0.5 * m_eff * MIN_SEPARATION * MIN_SEPARATION
}

/// The most kinetic energy an impact model's solution may add, as a share of the kinetic
/// energy the impact's balls had before it: the impact solver's tolerance ([`TOLERANCE`],
/// 5e-10). In exact arithmetic no model adds any (restitution e <= 1, friction dissipates).
/// Within a phase whose friction directions are fixed the frictional solver's laws are constant
/// per unit impulse, so its integrator (exact for polynomials) gives the velocities, and the
/// energy, to rounding; only where a slip turns are they integrated to the tolerance, and
/// friction dissipates there. Measured: at most 3.6e-16 of the impact's energy over 200,000
/// random impacts of both models, half with restitution 1 and a third without friction, at
/// speeds to 30 m/s, any ball mass and size (`engine/tests/impact_models.rs`, which asserts
/// this bound).
pub const IMPACT_ENERGY_SHARE: f64 = TOLERANCE;

/// The most energy event `e` may add, J: its kind's push ([`energy_allowance`]) and, for an
/// impact, [`IMPACT_ENERGY_SHARE`] of the kinetic energy its balls had before it.
pub fn event_allowance(e: &Event, p: &Params) -> f64 {
    let push = energy_allowance(e.kind, p);
    match e.kind {
        EventKind::BallBall | EventKind::BallCushion => {
            let kinetic: f64 = e
                .before
                .iter()
                .map(|s| s.energy(p.ball_mass, p.inertia(), p.ball_radius, 0.0))
                .sum();
            push + IMPACT_ENERGY_SHARE * kinetic
        }
        _ => push,
    }
}

/// Every ball's state just before the events at time `t`: each track's last segment that
/// started before `t`, evaluated at `t` (the initial states for `t` = 0).
fn states_before(shot: &Shot, t: f64) -> Vec<BallState> {
    shot.tracks
        .iter()
        .map(|tr| {
            let i = tr.segments.partition_point(|s| s.t < t).max(1) - 1;
            let seg = &tr.segments[i];
            crate::motion::state_at(&seg.state, t - seg.t, &shot.params)
        })
        .collect()
}

/// One broken invariant.
#[derive(Clone, Debug, PartialEq)]
pub enum Violation {
    /// An event added more energy than its kind allows.
    EnergyGain {
        /// The event's index.
        event: usize,
        /// Its kind.
        kind: EventKind,
        /// Energy added, J.
        gain: f64,
        /// Its allowance, J.
        allowance: f64,
    },
    /// The energy rose between two events.
    EnergyRose {
        /// The index of the event it rose before.
        event: usize,
        /// By how much, J.
        rise: f64,
    },
    /// Two events out of time order.
    EventsOutOfOrder {
        /// The earlier event's time, s.
        first: f64,
        /// The later event's time, s.
        then: f64,
    },
    /// A state that is not finite.
    NonFinite {
        /// When, s.
        t: f64,
        /// Which ball.
        ball: String,
    },
    /// Two balls overlapping by more than [`MAX_OVERLAP`].
    Overlap {
        /// By how much, m.
        depth: f64,
        /// When, s.
        t: f64,
        /// The two balls.
        balls: (String, String),
    },
    /// A ball in play off the table (it left the cloth without an event).
    OffTable {
        /// When, s.
        t: f64,
        /// Which ball.
        ball: String,
        /// Where (plan), m.
        pos: [f64; 2],
    },
    /// A resting contact's micro-collision lifted a ball off the cloth.
    MicroCollisionLift {
        /// Which ball.
        ball: String,
        /// When, s.
        t: f64,
    },
    /// A pair parted by a micro-collision met again sooner than the cloth's accelerations
    /// allow ([`resting_contacts`]).
    Chatter {
        /// The two balls.
        balls: (String, String),
        /// When they met again, s.
        t: f64,
        /// After how long, s.
        gap: f64,
        /// The least time the bound allows, s.
        least: f64,
    },
    /// A ball an impact sent off the cloth without a `lift_off` event for it at that instant,
    /// or a `lift_off` event for a ball that did not leave the cloth there ([`flights`]).
    LiftOffUnmatched {
        /// Which ball.
        ball: String,
        /// When, s.
        t: f64,
    },
    /// A shot that ended at rest with a ball still moving.
    StillMoving {
        /// Which ball.
        ball: String,
        /// Its motion.
        motion: Motion,
    },
}

impl std::fmt::Display for Violation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Violation::EventsOutOfOrder { first, then } => {
                write!(f, "events out of order: {first} then {then}")
            }
            Violation::NonFinite { t, ball } => write!(f, "non-finite state of {ball} at t = {t}"),
            Violation::Overlap { depth, t, balls } => write!(
                f,
                "balls {} and {} overlap by {depth:.3e} m at t = {t}",
                balls.0, balls.1
            ),
            Violation::OffTable { t, ball, pos } => write!(
                f,
                "ball {ball} is off the table at t = {t}, at ({:.4}, {:.4}) m, still in play",
                pos[0], pos[1]
            ),
            Violation::LiftOffUnmatched { ball, t } => write!(
                f,
                "ball {ball} left the cloth at t = {t} without its one lift_off event, or a \
                 lift_off came without it leaving"
            ),
            Violation::MicroCollisionLift { ball, t } => write!(
                f,
                "a micro-collision lifted ball {ball} off the cloth at t = {t}"
            ),
            Violation::Chatter {
                balls,
                t,
                gap,
                least,
            } => write!(
                f,
                "balls {} and {} met again {gap:.3e} s after a micro-collision, at t = {t} \
                 (the cloth's accelerations allow no less than {least:.3e} s)",
                balls.0, balls.1
            ),
            Violation::StillMoving { ball, motion } => {
                write!(f, "ball {ball} did not stop ({})", motion.name())
            }
            Violation::EnergyGain {
                event,
                kind,
                gain,
                allowance,
            } => write!(
                f,
                "event {event} ({}) added {gain:.3e} J (allowance {allowance:.3e} J)",
                kind.name()
            ),
            Violation::EnergyRose { event, rise } => {
                write!(f, "the energy rose by {rise:.3e} J before event {event}")
            }
        }
    }
}

/// `violations` as one message, `None` when there are none.
pub fn report(violations: &[Violation]) -> Option<String> {
    let texts: Vec<String> = violations.iter().map(|v| v.to_string()).collect();
    (!texts.is_empty()).then(|| texts.join("; "))
}

/// The largest relative acceleration two balls on the cloth can have under `p`, m/s^2: twice
/// the largest acceleration of any law on the cloth, the largest friction (mu_slide,
/// mu_slide_low or mu_roll) times g, plus g |tilt| and |nap|.
pub fn largest_relative_acceleration(p: &Params) -> f64 {
    let friction = p.mu_slide.max(p.mu_slide_low).max(p.mu_roll);
    2.0 * (friction * p.g + p.g * p.tilt() + p.nap_drift.abs())
}

/// How far along the normal a pair's contact may be found from where an earlier contact of the
/// pair was, m: the contact detection accepts a crossing within 1e-9 m of the contact distance
/// less its 1e-10 m skin, and counts a pair within 1e-9 m of touching and approaching as
/// touching at once (after any change of law): the sum of the three.
pub const CONTACT_BAND: f64 = SKIN + VERIFY_TOL + TOUCH_TOL;

/// The least time after a micro-collision before the pair can meet again, s: they part at
/// [`MIN_SEPARATION`] (at least) and their normal distance turns back at no more than
/// [`largest_relative_acceleration`] a; it must come back to within [`CONTACT_BAND`] δ of where
/// they parted: the later root of s t - a t^2 / 2 = δ, (s + sqrt(s^2 - 2 a δ)) / a, or the
/// turn s / a where the distance never leaves the band. About 2 s / a - δ / s: the band
/// shortens the bound by about 2e-6 s.
pub fn least_remeet_gap(p: &Params) -> f64 {
    let (s, a) = (MIN_SEPARATION, largest_relative_acceleration(p));
    let disc = s * s - 2.0 * a * CONTACT_BAND;
    if disc > 0.0 {
        (s + disc.sqrt()) / a
    } else {
        s / a
    }
}

/// The resting contacts' invariants ([`crate::impact::separation`]): a micro-collision (an
/// approach of at most [`RESTING_APPROACH`]) lifts no ball off the cloth, and a pair of balls
/// on the cloth that it leaves parting at [`MIN_SEPARATION`] meets again no sooner than
/// [`least_remeet_gap`] (about 2 MIN_SEPARATION over their largest relative acceleration,
/// [`largest_relative_acceleration`]) unless something else touches one of them first: at
/// most about that acceleration / (2 MIN_SEPARATION) micro-collisions per pair per second.
pub fn resting_contacts(shot: &Shot) -> Vec<Violation> {
    let p = &shot.params;
    let least_gap = least_remeet_gap(p);
    let mut out = Vec::new();
    // Pairs whose last impact was a micro-collision leaving both on the cloth: (i, j, time).
    let mut parted: Vec<(usize, usize, f64)> = Vec::new();
    for e in &shot.events {
        let pair = (e.kind == EventKind::BallBall && e.balls.len() == 2)
            .then(|| (e.balls[0].min(e.balls[1]), e.balls[0].max(e.balls[1])));
        if let Some((i, j)) = pair
            && let Some(&(_, _, t0)) = parted.iter().find(|q| (q.0, q.1) == (i, j))
            && e.t - t0 < least_gap * (1.0 - 1e-6)
        {
            out.push(Violation::Chatter {
                balls: (shot.tracks[i].id.clone(), shot.tracks[j].id.clone()),
                t: e.t,
                gap: e.t - t0,
                least: least_gap,
            });
        }
        // An impact, a pot or a departure changes a ball's course: its pairs start afresh.
        let touches = matches!(
            e.kind,
            EventKind::BallBall
                | EventKind::BallCushion
                | EventKind::BallPocket
                | EventKind::BallOffTable
        );
        if touches {
            parted.retain(|q| !e.balls.contains(&q.0) && !e.balls.contains(&q.1));
        }
        let Some((i, j)) = pair else {
            continue;
        };
        if e.normal_speed.is_none_or(|v| v > RESTING_APPROACH) {
            continue;
        }
        for ((&b, before), after) in e.balls.iter().zip(&e.before).zip(&e.after) {
            if before.motion != Motion::Airborne && after.motion == Motion::Airborne {
                out.push(Violation::MicroCollisionLift {
                    ball: shot.tracks[b].id.clone(),
                    t: e.t,
                });
            }
        }
        if e.after.iter().all(|s| s.motion != Motion::Airborne) {
            parted.push((i, j, e.t));
        }
    }
    out
}

/// Every invariant `shot` breaks at its events: their order, finite states, overlaps deeper
/// than `max_overlap` between any two balls in play just after each event, the energy at and
/// between events, the resting contacts' ([`resting_contacts`]), and, for a shot that ended at
/// rest, every ball stopped.
pub fn events(shot: &Shot, max_overlap: f64) -> Vec<Violation> {
    let p = &shot.params;
    let r = p.ball_radius;
    let mut out = Vec::new();
    for w in shot.events.windows(2) {
        // NaN times are out of order too.
        let ordered = matches!(
            w[0].t.partial_cmp(&w[1].t),
            Some(Ordering::Less | Ordering::Equal)
        );
        if !ordered {
            out.push(Violation::EventsOutOfOrder {
                first: w[0].t,
                then: w[1].t,
            });
        }
    }
    // Rounding allowance on sums of a few joules.
    let round = |e: f64| 1e-12 * e.abs().max(1e-3);
    let starts: Vec<BallState> = shot.tracks.iter().map(|t| t.segments[0].state).collect();
    let mut last = energy(&starts, p);
    let mut last_t = 0.0;
    // Events at one instant change velocities, not positions: each instant's events are
    // applied in order from the states just before it, and the positions checked once.
    let mut k = 0;
    while k < shot.events.len() {
        let t = shot.events[k].t;
        let end = k + shot.events[k..].iter().take_while(|e| e.t == t).count();
        let mut now = states_before(shot, t);
        let eb = energy(&now, p);
        if eb > last + motion_allowance(p, now.len(), t - last_t) + round(last) {
            out.push(Violation::EnergyRose {
                event: k,
                rise: eb - last,
            });
        }
        last = eb;
        last_t = t;
        for (j, e) in shot.events[k..end].iter().enumerate() {
            for (&b, s) in e.balls.iter().zip(&e.after) {
                now[b] = *s;
                if !s.is_finite() {
                    out.push(Violation::NonFinite {
                        t,
                        ball: shot.tracks[b].id.clone(),
                    });
                }
            }
            let ea = energy(&now, p);
            let allowance = event_allowance(e, p);
            if ea > last + allowance + round(last) {
                out.push(Violation::EnergyGain {
                    event: k + j,
                    kind: e.kind,
                    gain: ea - last,
                    allowance,
                });
            }
            last = ea;
        }
        for (i, a) in now.iter().enumerate() {
            for (j, b) in now.iter().enumerate().skip(i + 1) {
                if !a.motion.in_play() || !b.motion.in_play() {
                    continue;
                }
                let depth = 2.0 * r - (a.pos - b.pos).norm();
                if depth > max_overlap {
                    out.push(Violation::Overlap {
                        depth,
                        t,
                        balls: (shot.tracks[i].id.clone(), shot.tracks[j].id.clone()),
                    });
                }
            }
        }
        k = end;
    }
    out.extend(resting_contacts(shot));
    out.extend(flights(shot));
    if shot.ending == Ending::AtRest {
        for (tr, s) in shot.tracks.iter().zip(shot.final_states()) {
            // A ball spinning in place with no sidespin decay spins for ever: the shot is over.
            let spins_for_ever = s.motion == Motion::Spinning && p.sidespin_decel == 0.0;
            if s.motion.is_moving() || (s.motion == Motion::Spinning && !spins_for_ever) {
                out.push(Violation::StillMoving {
                    ball: tr.id.clone(),
                    motion: s.motion,
                });
            }
        }
    }
    out
}

/// Every flight that an impact opens is announced by one `lift_off` event of its ball at the
/// impact's instant, after it, and no `lift_off` comes otherwise (formats.md, "Result").
pub fn flights(shot: &Shot) -> Vec<Violation> {
    let mut out = Vec::new();
    // Balls sent off the cloth at the current instant and not yet announced.
    let mut pending: Vec<usize> = Vec::new();
    let mut now = f64::NAN;
    let unmatched = |b: usize, t: f64| Violation::LiftOffUnmatched {
        ball: shot.tracks[b].id.clone(),
        t,
    };
    for e in &shot.events {
        if e.t != now {
            out.extend(pending.drain(..).map(|b| unmatched(b, now)));
            now = e.t;
        }
        if e.kind == EventKind::LiftOff {
            for &b in &e.balls {
                match pending.iter().position(|&q| q == b) {
                    Some(k) => {
                        pending.remove(k);
                    }
                    None => out.push(unmatched(b, e.t)),
                }
            }
            continue;
        }
        // A landing that bounces (`e_bed`) opens a flight too.
        let bounce = e.kind == EventKind::Transition(Transition::Landing);
        for ((&b, s0), s1) in e.balls.iter().zip(&e.before).zip(&e.after) {
            if s1.motion == Motion::Airborne && (bounce || s0.motion != Motion::Airborne) {
                pending.push(b);
            }
        }
    }
    out.extend(pending.drain(..).map(|b| unmatched(b, now)));
    out
}

/// Every invariant `shot` (simulated from `setup`) breaks: [`events`], [`positions`], and on
/// a grid of instants [`SAMPLE_INTERVAL`] apart and just around every event, overlaps deeper
/// than [`MAX_OVERLAP`], balls off the table and non-finite states.
pub fn audit(setup: &Setup, shot: &Shot) -> Vec<Violation> {
    let mut out = events(shot, MAX_OVERLAP);
    out.extend(positions(&setup.table, shot));
    let sweep = sweep(setup, shot, SAMPLE_INTERVAL);
    if let Some((t, ball)) = sweep.non_finite {
        out.push(Violation::NonFinite { t, ball });
    }
    if sweep.max_overlap > MAX_OVERLAP
        && let Some((t, a, b)) = sweep.worst
    {
        out.push(Violation::Overlap {
            depth: sweep.max_overlap,
            t,
            balls: (a, b),
        });
    }
    if let Some((t, ball, pos)) = sweep.escaped {
        out.push(Violation::OffTable { t, ball, pos });
    }
    out
}
