//! Runs a scene in rapier, step by step, applying the table laws rapier lacks, and digests the
//! same figures as our engine gives: impacts, landings, pots, slide-to-roll transitions, final
//! positions. A [`Rapier`] world can run a whole shot, or one stretch of it at a time from
//! states given by our engine (re-seeded).
//!
//! Reading the steps:
//! - An impact starts in the step in which a ball-ball or ball-cushion contact first carries an
//!   impulse. Its time is where the gap before the step, closed at the approach speed before
//!   the step, reaches zero (within that step); the states after it are those at the end of the
//!   contact (one step for a collision).
//! - A ball rolls while the cloth's friction on it is below the Coulomb limit (the contact
//!   sticks), its slip is below what sliding friction removes in one step, and it moves. The slide-to-roll time is where the slip speed, extrapolated from
//!   its last two values, reaches zero.
//! - The state of an impact before is the one at the start of the step in which it begins.
//! - A ball lands in the step in which its cloth contact carries an impulse again after a
//!   flight; the time is where its centre came down to height R, the state after is the one at
//!   the end of the step in which the soft cloth has stopped its fall (its downward speed below
//!   one step's worth of gravity, g dt: a few steps).
//! - A ball is pocketed when it overlaps a pocket's sensor (rapier finds overlaps at the start
//!   of a step, before it moves the bodies); the time is where its centre crossed the fall
//!   circle, by linear interpolation back over the step before.

use crate::digest::{Final, ImpactDigest, Parties, Roll, ShotDigest, Velocities};
use crate::rapier_world::{
    ImpactFriction, RapierBallState, TablePart, World, WorldConfig, rest_depth,
};
use crate::shapes::{ContactHeight, Feature, TableShapes};
use crate::table_laws::{rolling_resistance, sidespin_resistance};
use snooker_engine::ball::SLIP_RATE_FACTOR;
use snooker_engine::{BallState, Motion, Setup, Table, Vec3, motion};

/// The result of a rapier run (a whole shot or one stretch).
#[derive(Clone, Debug, PartialEq)]
pub struct RapierRun {
    /// What happened.
    pub digest: ShotDigest,
    /// Largest depth a ball sank into the cloth so far, m.
    pub sink: f64,
    /// Steps taken.
    pub steps: usize,
    /// False when the time limit ran out before the run's end (rest, or the impact it waited for).
    pub finished: bool,
}

/// Where a run stops.
#[derive(Clone, Copy)]
pub enum Until<'a> {
    /// When every ball is at rest or pocketed.
    Rest,
    /// At the end of the first impact that satisfies the predicate (or at rest).
    Impact(&'a dyn Fn(&ImpactDigest) -> bool),
}

/// Per-ball bookkeeping between steps.
#[derive(Clone, Copy, Debug, Default)]
struct BallTrack {
    rolling: bool,
    /// Off the cloth (no cloth contact carried an impulse in the last step).
    airborne: bool,
    /// The landing (index of its impact) whose fall the soft cloth is still stopping.
    landing: Option<usize>,
    /// Time and state at which the current slide began (the ball's last impact, or the start).
    slide_from: (f64, Velocities),
    /// Slip speeds at the end of the last two steps (older first).
    slips: [f64; 2],
}

/// A ball is at rest once its speed is below what rolling resistance removes in one step,
/// mu_r g dt (the integrator's resolution), and its spin below the matching R-scaled value.
fn at_rest(k: &RapierBallState, setup: &Setup, dt: f64) -> bool {
    let p = &setup.params;
    let v = p.mu_roll * p.g * dt;
    k.vel.norm() <= v
        && k.spin.norm() * p.ball_radius <= v.max(p.sidespin_decel * dt * p.ball_radius)
}

/// Depth a ball on the cloth has sunk into it, m.
fn depth(k: &RapierBallState, radius: f64) -> f64 {
    (radius - k.pos.z).max(0.0)
}

/// Horizontal slip of the cloth contact point of a ball: rapier puts the contact point at
/// mid-depth, R - depth/2 below the centre.
fn slip(k: &RapierBallState, radius: f64) -> f64 {
    let r = Vec3::new(0.0, 0.0, -(radius - 0.5 * depth(k, radius)));
    let u = k.vel + k.spin.cross(&r);
    Vec3::new(u.x, u.y, 0.0).norm()
}

/// The time within a step starting at `t0` at which a gap `gap` closing at `speed` closes.
fn closing_time(t0: f64, gap: f64, speed: f64, dt: f64) -> f64 {
    if speed > 0.0 {
        t0 + (gap / speed).clamp(0.0, dt)
    } else {
        t0
    }
}

/// Name of a table feature as the engine reports it.
fn feature_name(table: &Table, f: Feature) -> String {
    match f {
        Feature::Cushion(k) => table.cushions[k].name.clone(),
        Feature::Jaw(k) => table.jaws[k].name.clone(),
    }
}

/// rapier's counterpart of one of our engine's ball states, with the balls resting `sink`
/// deep in the cloth: a ball on the cloth sits at that depth, an airborne one at its height; a
/// rolling ball rolls on rapier's contact point, at mid-depth (R - sink/2 below the centre),
/// so that it does not start with a slip of sink/2R of its speed. `None` for a pocketed ball.
pub fn counterpart(s: &BallState, radius: f64, sink: f64) -> Option<RapierBallState> {
    match s.motion {
        Motion::Pocketed | Motion::OffTable => None,
        Motion::Airborne => Some(RapierBallState {
            pos: Vec3::new(s.pos.x, s.pos.y, s.pos.z.max(radius)),
            vel: s.vel,
            spin: s.spin,
        }),
        Motion::Rolling => {
            let w = Vec3::z().cross(&s.vel) / (radius - 0.5 * sink);
            Some(RapierBallState {
                pos: Vec3::new(s.pos.x, s.pos.y, radius - sink),
                vel: Vec3::new(s.vel.x, s.vel.y, 0.0),
                spin: Vec3::new(w.x, w.y, s.spin.z),
            })
        }
        Motion::Stationary | Motion::Spinning | Motion::Sliding => Some(RapierBallState {
            pos: Vec3::new(s.pos.x, s.pos.y, radius - sink),
            vel: Vec3::new(s.vel.x, s.vel.y, 0.0),
            spin: s.spin,
        }),
    }
}

/// A scene's rapier world, settled into the cloth, that runs a whole shot or one stretch of
/// it at a time.
pub struct Rapier<'a> {
    setup: &'a Setup,
    shapes: TableShapes,
    world: World,
    friction_off_near_cushions: bool,
    /// Depth of a ball resting in the cloth after settling, m.
    rest_depth: f64,
    /// Largest depth seen, m.
    sink: f64,
    run: RunState,
}

/// What one run (whole shot or stretch) has noted so far.
#[derive(Default)]
struct RunState {
    tracks: Vec<BallTrack>,
    impacts: Vec<ImpactDigest>,
    rolls: Vec<Roll>,
    pockets: Vec<Option<String>>,
    /// Contacts that carried an impulse in the last step, with the index of their impact.
    open: Vec<(Parties, usize)>,
}

impl<'a> Rapier<'a> {
    /// Builds the world of `setup` with `cfg`; its balls rest at the depth of
    /// [`rest_depth`].
    pub fn new(setup: &'a Setup, cfg: &WorldConfig) -> Rapier<'a> {
        let world = World::new(&setup.table, &setup.params, &setup.balls, cfg);
        let rest_depth = rest_depth(&setup.params, cfg);
        Rapier {
            setup,
            shapes: TableShapes::new(&setup.table, &setup.params, cfg.cushion_contact),
            world,
            friction_off_near_cushions: cfg.impact_friction == ImpactFriction::Off
                && cfg.cushion_contact == ContactHeight::Nose,
            rest_depth,
            sink: rest_depth,
            run: RunState::default(),
        }
    }

    fn dt(&self) -> f64 {
        self.world.dt()
    }

    /// Depth a resting ball sank into the cloth, m.
    pub fn rest_depth(&self) -> f64 {
        self.rest_depth
    }

    /// Runs from our engine's states `start` at time `t0` (each ball as [`counterpart`]
    /// places it) until `until` or until the clock reaches `max_time`.
    pub fn run(
        &mut self,
        t0: f64,
        start: &[BallState],
        until: Until<'_>,
        max_time: f64,
    ) -> RapierRun {
        let p = self.setup.params;
        let placed: Vec<Option<RapierBallState>> = start
            .iter()
            .map(|s| counterpart(&motion::settle(*s, &p), p.ball_radius, self.rest_depth))
            .collect();
        self.world.place(t0, &placed);
        self.run = RunState {
            tracks: start
                .iter()
                .zip(&placed)
                .map(|(s, k)| {
                    let settled = motion::settle(*s, &p);
                    let u = k.map_or(0.0, |k| slip(&k, p.ball_radius));
                    BallTrack {
                        rolling: settled.motion == Motion::Rolling,
                        airborne: settled.motion == Motion::Airborne,
                        slide_from: (t0, Velocities::from(s)),
                        slips: [u, u],
                        landing: None,
                    }
                })
                .collect(),
            pockets: start.iter().map(|_| None::<String>).collect(),
            ..RunState::default()
        };
        let mut steps = 0;
        let mut before = self.kinematics();
        let mut finished = false;
        let mut closing: Option<usize> = None;
        while self.world.time() < max_time {
            let t = self.world.time();
            self.prepare(&before);
            self.world.step();
            steps += 1;
            let now = self.kinematics();
            self.note_impacts(t, &before, &now);
            self.note_landings(t, &before, &now);
            self.note_pots(t, &before);
            self.note_rolls(t, &now);
            before = now;
            if let Until::Impact(ends) = until {
                closing = closing.or_else(|| self.run.impacts.iter().position(ends));
                if let Some(k) = closing
                    && !self.run.open.iter().any(|(_, i)| *i == k)
                {
                    finished = true;
                    break;
                }
            }
            if self.all_at_rest(&before) {
                finished = true;
                break;
            }
        }
        let run = std::mem::take(&mut self.run);
        let finals = before
            .iter()
            .zip(&run.pockets)
            .map(|(k, pocket)| Final {
                pos: k.pos,
                pocket: pocket.clone(),
            })
            .collect();
        RapierRun {
            digest: ShotDigest {
                ids: self.setup.balls.iter().map(|b| b.id.clone()).collect(),
                start: start.iter().map(Velocities::from).collect(),
                impacts: run.impacts,
                rolls: run.rolls,
                finals,
                duration: self.world.time(),
            },
            sink: self.sink,
            steps,
            finished,
        }
    }

    /// Loads for the next step: rolling resistance on rolling balls, sidespin resistance on
    /// all on the cloth (in the air spin is frozen, thesis §6.1.6); in the frictionless limit,
    /// no cloth friction for a ball about to touch a cushion.
    fn prepare(&mut self, before: &[RapierBallState]) {
        let p = self.setup.params;
        let dt = self.dt();
        for (i, k) in before.iter().enumerate() {
            if !self.world.in_play(i) {
                continue;
            }
            let track = &self.run.tracks[i];
            let mut load = if track.airborne {
                crate::table_laws::Load::zero()
            } else {
                sidespin_resistance(k.spin.z, &p, dt)
            };
            if track.rolling {
                // The ball rolls on rapier's contact point, at mid-depth.
                let arm = p.ball_radius - 0.5 * depth(k, p.ball_radius);
                load = load.plus(rolling_resistance(k.vel, &p, dt, arm));
            }
            self.world.set_load(i, load);
            if self.friction_off_near_cushions {
                // The impact happens in the step in which the gap closes: the gap is at most
                // what the ball covers in two steps.
                let near = self
                    .shapes
                    .nearest(k.pos)
                    .is_some_and(|(_, gap, _)| gap <= 2.0 * k.vel.norm() * dt);
                self.world.set_cloth_friction_off(i, near);
            }
        }
    }

    /// The parties a touch stands for, if it is an impact.
    fn parties_of(&self, ball: usize, other: TablePart, at: &[RapierBallState]) -> Option<Parties> {
        match other {
            TablePart::Ball(j) => Some(Parties::Balls(ball.min(j), ball.max(j))),
            TablePart::Cushion(_) | TablePart::Jaw(_) => {
                let (f, _, _) = self.shapes.nearest(at[ball].pos)?;
                let name = feature_name(&self.setup.table, f);
                Some(match f {
                    Feature::Cushion(_) => Parties::Cushion(ball, name),
                    Feature::Jaw(_) => Parties::Jaw(ball, name),
                })
            }
            TablePart::Cloth | TablePart::Pocket(_) => None,
        }
    }

    /// Gap before the step and its closing speed, for an impact's parties.
    fn gap_before(&self, c: &Parties, before: &[RapierBallState]) -> (f64, f64) {
        match c {
            Parties::Balls(a, b) => {
                let d = before[*b].pos - before[*a].pos;
                let n = d.normalize();
                let gap = d.norm() - 2.0 * self.setup.params.ball_radius;
                (gap, (before[*a].vel - before[*b].vel).dot(&n))
            }
            Parties::Cushion(a, _) | Parties::Jaw(a, _) => {
                match self.shapes.nearest(before[*a].pos) {
                    Some((_, gap, n)) => (gap, -before[*a].vel.dot(&n)),
                    None => (0.0, 0.0),
                }
            }
            Parties::Landing(a) => (
                before[*a].pos.z - self.setup.params.ball_radius,
                -before[*a].vel.z,
            ),
            Parties::Pocket(..) | Parties::OffTable(..) => (0.0, 0.0),
        }
    }

    fn velocities_of(c: &Parties, at: &[RapierBallState]) -> Vec<Velocities> {
        c.balls()
            .iter()
            .map(|&i| Velocities {
                vel: at[i].vel,
                spin: at[i].spin,
            })
            .collect()
    }

    /// Records the impact of `c` that began in the step from `t0` (state `before`) and left
    /// its balls with `after`: its time is where the closing gap ran out, and from there its
    /// balls slide with `after`. Returns its index.
    fn begin_impact(
        &mut self,
        c: &Parties,
        t0: f64,
        before: &[RapierBallState],
        after: Vec<Velocities>,
    ) -> usize {
        let dt = self.dt();
        let (gap, speed) = self.gap_before(c, before);
        let t = closing_time(t0, gap, speed, dt);
        for (&i, a) in c.balls().iter().zip(&after) {
            self.run.tracks[i].slide_from = (t, *a);
        }
        self.run.impacts.push(ImpactDigest {
            t,
            parties: c.clone(),
            before: Self::velocities_of(c, before),
            after,
            end: t0 + dt,
            approach: speed,
        });
        self.run.impacts.len() - 1
    }

    /// Impacts: contacts that start carrying an impulse open an impact; contacts that go on
    /// carrying one update its state after.
    fn note_impacts(&mut self, t0: f64, before: &[RapierBallState], now: &[RapierBallState]) {
        let dt = self.dt();
        let mut current: Vec<Parties> = Vec::new();
        for touch in self.world.touches() {
            if let Some(c) = self.parties_of(touch.ball, touch.other, before)
                && !current.contains(&c)
            {
                current.push(c);
            }
        }
        let mut open = Vec::new();
        for c in current {
            let after = Self::velocities_of(&c, now);
            if let Some(&(_, idx)) = self.run.open.iter().find(|(o, _)| *o == c) {
                self.run.impacts[idx].after = after;
                self.run.impacts[idx].end = t0 + dt;
                open.push((c, idx));
            } else {
                let k = self.begin_impact(&c, t0, before, after);
                open.push((c, k));
            }
        }
        self.run.open = open;
    }

    /// Landings: an airborne ball whose cloth contact carries an impulse again, until the cloth
    /// has stopped its fall. A ball whose cloth contact carries none has left the cloth.
    fn note_landings(&mut self, t0: f64, before: &[RapierBallState], now: &[RapierBallState]) {
        let dt = self.dt();
        let settled = self.setup.params.g * dt;
        let mut on_cloth = vec![false; self.world.len()];
        for touch in self.world.touches() {
            if touch.other == TablePart::Cloth {
                on_cloth[touch.ball] = true;
            }
        }
        for (i, &touching) in on_cloth.iter().enumerate() {
            if !self.world.in_play(i) {
                continue;
            }
            let track = &mut self.run.tracks[i];
            if let Some(k) = track.landing {
                let landing = &mut self.run.impacts[k];
                landing.after = Self::velocities_of(&landing.parties, now);
                landing.end = t0 + dt;
                track.slide_from.1 = landing.after[0];
                if now[i].vel.z >= -settled {
                    track.landing = None;
                } else {
                    self.run.open.push((Parties::Landing(i), k));
                }
                continue;
            }
            if !track.airborne {
                track.airborne = !touching;
                continue;
            }
            if !touching {
                continue;
            }
            track.airborne = false;
            let c = Parties::Landing(i);
            let after = Self::velocities_of(&c, now);
            let k = self.begin_impact(&c, t0, before, after);
            if now[i].vel.z < -settled {
                self.run.tracks[i].landing = Some(k);
                self.run.open.push((c, k));
            }
        }
    }

    /// Pots: a ball overlapping a pocket's sensor leaves play.
    fn note_pots(&mut self, t0: f64, before: &[RapierBallState]) {
        let dt = self.dt();
        for (i, b) in before.iter().enumerate() {
            if !self.world.in_play(i) {
                continue;
            }
            let Some(k) = self.world.pocket_of(i) else {
                continue;
            };
            let pk = &self.setup.table.pockets[k];
            let plan = |v: Vec3| Vec3::new(v.x, v.y, 0.0);
            let d = plan(b.pos - pk.centre);
            let gap = d.norm() - pk.radius;
            let speed = -plan(b.vel).dot(&d.normalize());
            let now = self.world.kinematics(i);
            let approach = plan(b.vel).norm();
            // rapier detects overlaps before it moves the bodies: the overlap seen after a step
            // is the one at its start, so the centre crossed the fall circle within the step
            // before (gap <= 0 here).
            let t = if speed > 0.0 {
                t0 + (gap / speed).clamp(-dt, 0.0)
            } else {
                t0
            };
            self.run.impacts.push(ImpactDigest {
                t,
                parties: Parties::Pocket(i, pk.name.clone()),
                before: vec![Velocities {
                    vel: b.vel,
                    spin: b.spin,
                }],
                after: vec![Velocities {
                    vel: now.vel,
                    spin: now.spin,
                }],
                end: t,
                approach,
            });
            self.run.pockets[i] = Some(pk.name.clone());
            self.world.remove(i);
        }
    }

    /// Slide-to-roll: the cloth contact of a moving ball starts sticking.
    fn note_rolls(&mut self, t0: f64, now: &[RapierBallState]) {
        let p = self.setup.params;
        let dt = self.dt();
        let mut cloth = vec![None; self.world.len()];
        for touch in self.world.touches() {
            if touch.other == TablePart::Cloth {
                cloth[touch.ball] = Some(touch);
            }
        }
        for (i, k) in now.iter().enumerate() {
            if !self.world.in_play(i) {
                continue;
            }
            let u = slip(k, p.ball_radius);
            self.sink = self.sink.max(depth(k, p.ball_radius));
            let friction_off = self.world.cloth_friction_off(i);
            let track = &mut self.run.tracks[i];
            let [older, last] = track.slips;
            track.slips = [last, u];
            // Without friction in this step (a frictionless cushion impact) nothing is learnt.
            if p.mu_slide <= 0.0 || friction_off {
                track.rolling = false;
                continue;
            }
            // Sliding friction shrinks the slip by 3.5 mu_s g per second (physics.md): a slip
            // below one step's worth ends within the step.
            let small = u <= SLIP_RATE_FACTOR * p.mu_slide * p.g * dt;
            let sticks = cloth[i]
                .is_some_and(|c| c.tangent_impulse < (1.0 - 1e-6) * p.mu_slide * c.normal_impulse);
            let rolling = sticks && small && !at_rest(k, self.setup, dt);
            if rolling && !track.rolling {
                let rate = (older - last) / dt;
                let (slide_t, start) = track.slide_from;
                self.run.rolls.push(Roll {
                    ball: i,
                    t: closing_time(t0, last, rate, dt),
                    speed: Vec3::new(k.vel.x, k.vel.y, 0.0).norm(),
                    slide_t,
                    slide_start: start,
                });
            }
            track.rolling = rolling;
        }
    }

    fn all_at_rest(&self, now: &[RapierBallState]) -> bool {
        let dt = self.dt();
        now.iter()
            .enumerate()
            .all(|(i, k)| !self.world.in_play(i) || at_rest(k, self.setup, dt))
    }

    fn kinematics(&self) -> Vec<RapierBallState> {
        (0..self.world.len())
            .map(|i| self.world.kinematics(i))
            .collect()
    }
}

/// Runs `setup`'s whole shot in rapier with `cfg` until every ball rests or `max_time`
/// seconds pass.
pub fn run(setup: &Setup, cfg: &WorldConfig, max_time: f64) -> RapierRun {
    let mut rapier = Rapier::new(setup, cfg);
    let start: Vec<BallState> = setup.balls.iter().map(|b| b.state).collect();
    rapier.run(0.0, &start, Until::Rest, max_time)
}
