//! Runs a scene in rapier, step by step, applying the table laws rapier lacks, and records the
//! same figures as our engine gives: impacts, pots, slide-to-roll transitions, final positions.
//!
//! Reading the steps:
//! - An impact starts in the step in which a ball-ball or ball-cushion contact first carries an
//!   impulse. Its time is where the gap before the step, closed at the approach speed before
//!   the step, reaches zero (within that step); the states after it are those at the end of the
//!   contact (one step for a collision).
//! - A ball rolls while the cloth's friction on it is below the Coulomb limit (the contact
//!   sticks), its slip is below what sliding friction removes in one step, and it moves. The slide-to-roll time is where the slip speed, extrapolated from
//!   its last two values, reaches zero.
//! - A ball is pocketed in the step in which it overlaps a pocket's sensor; the time is where
//!   its centre crossed the fall circle, by linear interpolation.

use crate::rapier_world::{Body, ImpactFriction, Kinematics, World, WorldConfig};
use crate::record::{Contact, Final, Impact, Record, Roll, Velocities};
use crate::shapes::{CushionContact, Feature, TableShapes};
use crate::table_laws::{rolling_resistance, sidespin_resistance};
use snooker_engine::{Setup, Table, Vec3};

/// Longest time the resting balls are given to sink into rapier's soft cloth, s.
const SETTLE_TIME: f64 = 1.0;

/// The result of a rapier run.
#[derive(Clone, Debug, PartialEq)]
pub struct RapierRun {
    /// What happened.
    pub record: Record,
    /// Largest depth a ball sank into the cloth during the run, m.
    pub sink: f64,
    /// Steps taken.
    pub steps: usize,
    /// False when `max_time` ran out before the balls stopped.
    pub finished: bool,
}

/// Per-ball bookkeeping between steps.
#[derive(Clone, Copy, Debug, Default)]
struct BallTrack {
    rolling: bool,
    /// Time and state at which the current slide began (the ball's last impact, or the start).
    slide_from: (f64, Option<Velocities>),
    /// Slip speeds at the end of the last two steps (older first).
    slips: [f64; 2],
}

/// A ball is at rest once its speed is below what rolling resistance removes in one step,
/// mu_r g dt (the integrator's resolution), and its spin below the matching R-scaled value.
fn at_rest(k: &Kinematics, setup: &Setup, dt: f64) -> bool {
    let p = &setup.params;
    let v = p.mu_roll * p.g * dt;
    k.vel.norm() <= v
        && k.spin.norm() * p.ball_radius <= v.max(p.sidespin_decel * dt * p.ball_radius)
}

/// Depth a ball on the cloth has sunk into it, m.
fn depth(k: &Kinematics, radius: f64) -> f64 {
    (radius - k.pos.z).max(0.0)
}

/// Horizontal slip of the cloth contact point of a ball: rapier puts the contact point at
/// mid-depth, R - depth/2 below the centre.
fn slip(k: &Kinematics, radius: f64) -> f64 {
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

struct Runner<'a> {
    setup: &'a Setup,
    shapes: TableShapes,
    world: World,
    tracks: Vec<BallTrack>,
    impacts: Vec<Impact>,
    rolls: Vec<Roll>,
    pockets: Vec<Option<String>>,
    /// Contacts that carried an impulse in the last step, with the index of their impact.
    open: Vec<(Contact, usize)>,
    friction_off_near_cushions: bool,
    sink: f64,
    initial: Vec<Velocities>,
}

impl Runner<'_> {
    fn dt(&self) -> f64 {
        self.world.dt()
    }

    /// Loads for the next step: rolling resistance on rolling balls, sidespin resistance on
    /// all; in the frictionless limit, no cloth friction for a ball about to touch a cushion.
    fn prepare(&mut self, before: &[Kinematics]) {
        let p = self.setup.params;
        let dt = self.dt();
        for (i, k) in before.iter().enumerate() {
            if !self.world.in_play(i) {
                continue;
            }
            let mut load = sidespin_resistance(k.spin.z, &p, dt);
            if self.tracks[i].rolling {
                load = load.plus(rolling_resistance(k.vel, &p, dt));
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

    /// The contact a touch stands for, if it is an impact.
    fn contact_of(&self, ball: usize, other: Body, at: &[Kinematics]) -> Option<Contact> {
        match other {
            Body::Ball(j) => Some(Contact::Balls(ball.min(j), ball.max(j))),
            Body::Cushion(_) | Body::Jaw(_) => {
                let (f, _, _) = self.shapes.nearest(at[ball].pos)?;
                Some(Contact::Cushion(ball, feature_name(&self.setup.table, f)))
            }
            Body::Cloth | Body::Pocket(_) => None,
        }
    }

    /// Gap before the step and its closing speed, for a contact.
    fn gap_before(&self, c: &Contact, before: &[Kinematics]) -> (f64, f64) {
        match c {
            Contact::Balls(a, b) => {
                let d = before[*b].pos - before[*a].pos;
                let n = d.normalize();
                let gap = d.norm() - 2.0 * self.setup.params.ball_radius;
                (gap, (before[*a].vel - before[*b].vel).dot(&n))
            }
            Contact::Cushion(a, _) => match self.shapes.nearest(before[*a].pos) {
                Some((_, gap, n)) => (gap, -before[*a].vel.dot(&n)),
                None => (0.0, 0.0),
            },
            Contact::Pocket(..) => (0.0, 0.0),
        }
    }

    fn after_of(c: &Contact, now: &[Kinematics]) -> Vec<Velocities> {
        c.balls()
            .iter()
            .map(|&i| Velocities {
                vel: now[i].vel,
                spin: now[i].spin,
            })
            .collect()
    }

    /// Impacts: contacts that start carrying an impulse open an impact; contacts that go on
    /// carrying one update its state after.
    fn record_impacts(&mut self, t0: f64, before: &[Kinematics], now: &[Kinematics]) {
        let dt = self.dt();
        let mut current: Vec<Contact> = Vec::new();
        for touch in self.world.touches() {
            if let Some(c) = self.contact_of(touch.ball, touch.other, before)
                && !current.contains(&c)
            {
                current.push(c);
            }
        }
        let mut open = Vec::new();
        for c in current {
            let after = Self::after_of(&c, now);
            if let Some(&(_, idx)) = self.open.iter().find(|(o, _)| *o == c) {
                self.impacts[idx].after = after;
                open.push((c, idx));
            } else {
                let (gap, speed) = self.gap_before(&c, before);
                let t = closing_time(t0, gap, speed, dt);
                for (&i, a) in c.balls().iter().zip(&after) {
                    self.tracks[i].slide_from = (t, Some(*a));
                }
                self.impacts.push(Impact {
                    t,
                    contact: c.clone(),
                    after,
                    approach: speed,
                });
                open.push((c, self.impacts.len() - 1));
            }
        }
        self.open = open;
    }

    /// Pots: a ball overlapping a pocket's sensor leaves play.
    fn record_pots(&mut self, t0: f64, before: &[Kinematics]) {
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
            self.impacts.push(Impact {
                t: closing_time(t0, gap, speed, dt),
                contact: Contact::Pocket(i, pk.name.clone()),
                after: vec![Velocities {
                    vel: now.vel,
                    spin: now.spin,
                }],
                approach,
            });
            self.pockets[i] = Some(pk.name.clone());
            self.world.remove(i);
        }
    }

    /// Slide-to-roll: the cloth contact of a moving ball starts sticking.
    fn record_rolls(&mut self, t0: f64, now: &[Kinematics]) {
        let p = self.setup.params;
        let dt = self.dt();
        let mut cloth = vec![None; self.world.len()];
        for touch in self.world.touches() {
            if touch.other == Body::Cloth {
                cloth[touch.ball] = Some(touch);
            }
        }
        for (i, k) in now.iter().enumerate() {
            if !self.world.in_play(i) {
                continue;
            }
            let u = slip(k, p.ball_radius);
            self.sink = self.sink.max(depth(k, p.ball_radius));
            let track = &mut self.tracks[i];
            let [older, last] = track.slips;
            track.slips = [last, u];
            // Without friction in this step (a frictionless cushion impact) nothing is learnt.
            if p.mu_slide <= 0.0 || self.world.cloth_friction_off(i) {
                track.rolling = false;
                continue;
            }
            // Sliding friction shrinks the slip by 3.5 mu_s g per second (physics.md): a slip
            // below one step's worth ends within the step.
            let small = u <= 3.5 * p.mu_slide * p.g * dt;
            let sticks = cloth[i]
                .is_some_and(|c| c.tangent_impulse < (1.0 - 1e-6) * p.mu_slide * c.normal_impulse);
            let rolling = sticks && small && !at_rest(k, self.setup, dt);
            if rolling && !track.rolling {
                let rate = (older - last) / dt;
                let (slide_t, start) = track.slide_from;
                self.rolls.push(Roll {
                    ball: i,
                    t: closing_time(t0, last, rate, dt),
                    speed: Vec3::new(k.vel.x, k.vel.y, 0.0).norm(),
                    slide_t,
                    slide_start: start.unwrap_or(self.initial[i]),
                });
            }
            track.rolling = rolling;
        }
    }

    fn all_at_rest(&self, now: &[Kinematics]) -> bool {
        let dt = self.dt();
        now.iter()
            .enumerate()
            .all(|(i, k)| !self.world.in_play(i) || at_rest(k, self.setup, dt))
    }

    fn kinematics(&self) -> Vec<Kinematics> {
        (0..self.world.len())
            .map(|i| self.world.kinematics(i))
            .collect()
    }
}

/// Runs `setup` in rapier with `cfg` until every ball rests or `max_time` seconds pass.
pub fn run(setup: &Setup, cfg: &WorldConfig, max_time: f64) -> RapierRun {
    let mut world = World::new(&setup.table, &setup.params, &setup.balls, cfg);
    let sink = world.launch(&setup.balls, SETTLE_TIME);
    let n = setup.balls.len();
    let mut r = Runner {
        setup,
        shapes: TableShapes::new(&setup.table, &setup.params, cfg.cushion_contact),
        world,
        tracks: vec![BallTrack::default(); n],
        impacts: Vec::new(),
        rolls: Vec::new(),
        pockets: vec![None; n],
        open: Vec::new(),
        friction_off_near_cushions: cfg.impact_friction == ImpactFriction::Off
            && cfg.cushion_contact == CushionContact::Nose,
        sink,
        initial: setup
            .balls
            .iter()
            .map(|b| Velocities {
                vel: b.state.vel,
                spin: b.state.spin,
            })
            .collect(),
    };
    let mut steps = 0;
    let mut before = r.kinematics();
    let mut finished = false;
    while r.world.time() < max_time {
        let t0 = r.world.time();
        r.prepare(&before);
        r.world.step();
        steps += 1;
        let now = r.kinematics();
        r.record_impacts(t0, &before, &now);
        r.record_pots(t0, &before);
        r.record_rolls(t0, &now);
        if r.all_at_rest(&now) {
            finished = true;
            before = now;
            break;
        }
        before = now;
    }
    let finals = before
        .iter()
        .zip(&r.pockets)
        .map(|(k, pocket)| Final {
            pos: k.pos,
            pocket: pocket.clone(),
        })
        .collect();
    RapierRun {
        record: Record {
            ids: setup.balls.iter().map(|b| b.id.clone()).collect(),
            impacts: r.impacts,
            rolls: r.rolls,
            finals,
            duration: r.world.time(),
        },
        sink: r.sink,
        steps,
        finished,
    }
}
