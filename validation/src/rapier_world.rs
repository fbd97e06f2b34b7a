//! A scene as a rapier world.
//!
//! - Balls: dynamic spheres of the scene's radius and mass; rapier gives a solid sphere the
//!   inertia 2 M R^2 / 5, the engine's [`Params::inertia`].
//! - Cloth: a fixed half-space z <= 0 (our engine's cloth is endless too: a ball leaves it only
//!   by entering a pocket's fall).
//! - Cushions, jaws and pockets: the solids of [`crate::shapes`] (pockets as sensors).
//! - Friction and restitution per pair, set by a contact hook from the scene's parameters.

use crate::shapes::{ContactHeight, TableShapes};
use crate::table_laws::Load;
use rapier3d_f64::math::Vector;
use rapier3d_f64::prelude::*;
use snooker_engine::{Ball, Params, Table, Vec3};

/// The part of the table (or the ball) a rapier collider stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TablePart {
    /// The cloth.
    Cloth,
    /// Ball `i` of the scene.
    Ball(usize),
    /// Straight cushion `k` of the table (nose or pocket facing).
    Cushion(usize),
    /// Jaw `k` of the table.
    Jaw(usize),
    /// Pocket `k` of the table (a sensor).
    Pocket(usize),
}

impl TablePart {
    fn encode(self) -> u128 {
        let (tag, i) = match self {
            TablePart::Cloth => (0u128, 0usize),
            TablePart::Ball(i) => (1, i),
            TablePart::Cushion(i) => (2, i),
            TablePart::Jaw(i) => (3, i),
            TablePart::Pocket(i) => (4, i),
        };
        (tag << 64) | i as u128
    }

    fn decode(data: u128) -> TablePart {
        let i = (data & u64::MAX as u128) as usize;
        match data >> 64 {
            1 => TablePart::Ball(i),
            2 => TablePart::Cushion(i),
            3 => TablePart::Jaw(i),
            4 => TablePart::Pocket(i),
            _ => TablePart::Cloth,
        }
    }
}

/// How the impacts are treated in rapier.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImpactFriction {
    /// The frictionless limit of the thesis's models (physics.md, "Analytic limits"): no
    /// ball-ball or ball-cushion friction, and no cloth friction during a cushion impact
    /// (mu_s = 0 during the impact), so that the velocity along the cushion is kept.
    Off,
    /// Ball-ball friction mu_ball, cushion friction mu_cushion, and the cloth's friction acting
    /// on the cloth's reaction during the impact, as in the thesis's 3D models (§6.1, §6.2).
    On,
}

/// Change of a resting ball's depth over [`SETTLE_CHECK`] steps below which it has settled
/// into the cloth, m. rapier corrects the penetration of its soft contacts through the
/// positions, not the velocities, so a sinking ball's velocity reads zero: the depth itself is
/// watched (it approaches the contact spring's static deflection g / (2 pi f)^2 with a time
/// constant of about a third of a second).
pub const SETTLED_DEPTH_CHANGE: f64 = 1e-10;

/// Steps between two looks at the depth while settling.
pub const SETTLE_CHECK: usize = 100;

/// Depth a ball resting on the cloth sinks into it in rapier with the contacts of `cfg`, m:
/// measured once per (ball, contact settings) on a world of one ball, then cached (every ball
/// of a scene has the same radius and mass). Balls are placed at this depth rather than settled
/// together at the start of every run, which would cost seconds of simulated time per run.
pub fn rest_depth(params: &Params, cfg: &WorldConfig) -> f64 {
    type Key = [u64; 6];
    static CACHE: std::sync::Mutex<Vec<(Key, f64)>> = std::sync::Mutex::new(Vec::new());
    let key: Key = [
        params.ball_radius,
        params.ball_mass,
        params.g,
        cfg.dt,
        cfg.contact_hz,
        cfg.contact_damping,
    ]
    .map(f64::to_bits);
    let cached = |c: &[(Key, f64)]| c.iter().find(|(k, _)| *k == key).map(|&(_, d)| d);
    if let Some(d) = CACHE.lock().ok().and_then(|c| cached(&c)) {
        return d;
    }
    let ball = Ball {
        id: "probe".into(),
        kind: snooker_engine::BallKind::Other,
        state: snooker_engine::BallState::at_rest(0.0, 0.0, params.ball_radius),
    };
    let mut w = World::new(&Table::open(), params, &[ball], cfg);
    let d = w.settle(SETTLE_TIME);
    if let Ok(mut c) = CACHE.lock() {
        c.push((key, d));
    }
    d
}

/// Longest time a resting ball is given to sink into rapier's soft cloth, s (it settles within
/// about 3.5 s: ten time constants).
const SETTLE_TIME: f64 = 5.0;

/// rapier's settings for a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorldConfig {
    /// Time step, s.
    pub dt: f64,
    /// Friction during impacts.
    pub impact_friction: ImpactFriction,
    /// The cushions' restitution is the compliant cushion's for each impact's normal speed
    /// (`snooker_engine::impact::impulse::Backing::restitution`), not e_e.
    pub compliant_cushion: bool,
    /// Natural frequency of the soft contacts, Hz (rapier's default: 30 between bodies, 60
    /// against fixed bodies).
    pub contact_hz: f64,
    /// Damping ratio of the soft contacts (rapier's default: 10).
    pub contact_damping: f64,
    /// Solver iterations per step (rapier's default: 4).
    pub solver_iterations: usize,
    /// Where the cushions touch the balls.
    pub cushion_contact: ContactHeight,
}

impl WorldConfig {
    /// rapier's default contact softness and solver, at time step `dt`, the cushions touching
    /// at the nose height with friction on and level in the frictionless limit (see
    /// [`ContactHeight`]).
    pub fn new(dt: f64, impact_friction: ImpactFriction) -> WorldConfig {
        WorldConfig {
            dt,
            impact_friction,
            compliant_cushion: false,
            cushion_contact: match impact_friction {
                ImpactFriction::On => ContactHeight::Nose,
                ImpactFriction::Off => ContactHeight::Level,
            },
            contact_hz: 60.0,
            contact_damping: 10.0,
            solver_iterations: 4,
        }
    }
}

/// The per-pair friction and restitution, applied by rapier's contact-modification hook.
struct ContactRules {
    params: Params,
    impact_friction: ImpactFriction,
    /// The compliant cushion's restitution ([`WorldConfig::compliant_cushion`]).
    compliant_cushion: bool,
    /// Per ball: the cloth's friction is off during this step (a frictionless cushion impact).
    cloth_friction_off: Vec<bool>,
}

impl ContactRules {
    /// (friction, restitution) for a pair of bodies, the ball's contact approaching the other
    /// at `approach` (m/s, in plan).
    fn coefficients(&self, a: TablePart, b: TablePart, approach: f64) -> (f64, f64) {
        let p = &self.params;
        let on = self.impact_friction == ImpactFriction::On;
        let (ball, other) = match (a, b) {
            (TablePart::Ball(i), o) | (o, TablePart::Ball(i)) => (i, o),
            _ => return (0.0, 0.0),
        };
        match other {
            // Thesis §6.1: mu_bb, e (Newton's restitution in rapier, energetic in ours).
            TablePart::Ball(_) => (if on { p.mu_ball } else { 0.0 }, p.e_ball),
            // Thesis §6.2: mu_w, e_e at the nose.
            TablePart::Cushion(_) | TablePart::Jaw(_) => {
                let e = if self.compliant_cushion {
                    p.cushion_backing()
                        .restitution(p.e_cushion, p.ball_mass, approach)
                } else {
                    p.e_cushion
                };
                (if on { p.mu_cushion } else { 0.0 }, e)
            }
            // Thesis §2.4.2: sliding friction mu_s; the cloth does not bounce.
            TablePart::Cloth => (
                if self.cloth_friction_off.get(ball).copied().unwrap_or(false) {
                    0.0
                } else {
                    p.mu_slide
                },
                0.0,
            ),
            TablePart::Pocket(_) => (0.0, 0.0),
        }
    }
}

impl PhysicsHooks for ContactRules {
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        let a = TablePart::decode(ctx.colliders[ctx.collider1].user_data);
        let b = TablePart::decode(ctx.colliders[ctx.collider2].user_data);
        // The ball's speed in plan along the contact normal (only the compliant cushion's
        // restitution depends on it).
        let approach = if self.compliant_cushion {
            let ball_body = match a {
                TablePart::Ball(_) => ctx.rigid_body1,
                _ => ctx.rigid_body2,
            };
            let normal = ctx.rigid_mut().map(|m| *m.normal);
            let n = normal.map_or(Vec3::zeros(), |v| Vec3::new(v.x, v.y, 0.0));
            match ball_body.and_then(|h| ctx.bodies.get(h)) {
                Some(body) if n.norm() > 0.0 => {
                    let v = body.linvel();
                    Vec3::new(v.x, v.y, 0.0).dot(&n).abs() / n.norm()
                }
                _ => 0.0,
            }
        } else {
            0.0
        };
        let (friction, restitution) = self.coefficients(a, b, approach);
        if let Some(m) = ctx.rigid_mut() {
            *m.friction = friction;
            *m.restitution = restitution;
        }
    }
}

/// A contact of a ball seen after a step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Touch {
    /// The ball.
    pub ball: usize,
    /// What it touches.
    pub other: TablePart,
    /// Normal impulse of the step, N s.
    pub normal_impulse: f64,
    /// Magnitude of the friction impulse of the step, N s.
    pub tangent_impulse: f64,
}

/// Position, velocity and spin of a ball in rapier, table frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RapierBallState {
    /// Centre, m.
    pub pos: Vec3,
    /// Velocity, m/s.
    pub vel: Vec3,
    /// Angular velocity, rad/s.
    pub spin: Vec3,
}

struct Slot {
    body: RigidBodyHandle,
    collider: ColliderHandle,
    in_play: bool,
}

/// A scene built as a rapier world.
pub struct World {
    phys: PhysicsWorld,
    rules: ContactRules,
    balls: Vec<Slot>,
    pockets: Vec<ColliderHandle>,
    params: Params,
    time: f64,
}

fn to_glam(v: Vec3) -> Vector {
    Vector::new(v.x, v.y, v.z)
}

fn from_glam(v: Vector) -> Vec3 {
    Vec3::new(v.x, v.y, v.z)
}

impl World {
    /// Builds the world for `table` and `balls` (their starting states are applied by
    /// [`World::place`], at the depth of [`rest_depth`] for balls on the cloth).
    pub fn new(table: &Table, params: &Params, balls: &[Ball], cfg: &WorldConfig) -> World {
        let mut phys = PhysicsWorld::new();
        phys.gravity = Vector::new(0.0, 0.0, -params.g);
        let ip = &mut phys.integration_parameters;
        ip.dt = cfg.dt;
        ip.num_solver_iterations = cfg.solver_iterations;
        // One Coulomb friction constraint per contact point, no "twist" constraint (which
        // would resist spin about the contact normal: the cloth's sidespin law is ours).
        ip.friction_model = FrictionModel::Coulomb;
        ip.contact_recycling = false;
        ip.contact_softness = SpringCoefficients::new(cfg.contact_hz, cfg.contact_damping);
        ip.static_contact_softness = SpringCoefficients::new(cfg.contact_hz, cfg.contact_damping);

        let fixed = phys.insert_body(RigidBodyBuilder::fixed());
        let add_fixed = |phys: &mut PhysicsWorld, c: ColliderBuilder| {
            phys.insert_collider(c, Some(fixed));
        };
        add_fixed(
            &mut phys,
            ColliderBuilder::new(SharedShape::halfspace(Vector::Z))
                .user_data(TablePart::Cloth.encode()),
        );
        let shapes = TableShapes::new(table, params, cfg.cushion_contact);
        for (k, c) in shapes.noses.iter().enumerate() {
            add_fixed(
                &mut phys,
                ColliderBuilder::capsule_from_endpoints(to_glam(c.a), to_glam(c.b), c.radius)
                    .user_data(TablePart::Cushion(k).encode()),
            );
        }
        for (k, j) in shapes.jaws.iter().enumerate() {
            add_fixed(
                &mut phys,
                ColliderBuilder::ball(j.radius)
                    .translation(to_glam(j.centre))
                    .user_data(TablePart::Jaw(k).encode()),
            );
        }
        let mut pockets = Vec::new();
        for (k, pk) in shapes.pockets.iter().enumerate() {
            let h = phys.insert_collider(
                ColliderBuilder::ball(pk.radius)
                    .translation(to_glam(pk.centre))
                    .sensor(true)
                    .user_data(TablePart::Pocket(k).encode()),
                Some(fixed),
            );
            pockets.push(h);
        }
        let mut slots = Vec::new();
        for (i, b) in balls.iter().enumerate() {
            let body = phys.insert_body(
                RigidBodyBuilder::dynamic()
                    .translation(to_glam(Vec3::new(
                        b.state.pos.x,
                        b.state.pos.y,
                        b.state.pos.z.max(params.ball_radius),
                    )))
                    .can_sleep(false),
            );
            let collider = phys.insert_collider(
                ColliderBuilder::ball(params.ball_radius)
                    .mass(params.ball_mass)
                    .active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS)
                    .user_data(TablePart::Ball(i).encode()),
                Some(body),
            );
            slots.push(Slot {
                body,
                collider,
                in_play: true,
            });
        }
        World {
            phys,
            rules: ContactRules {
                params: *params,
                impact_friction: cfg.impact_friction,
                compliant_cushion: cfg.compliant_cushion,
                cloth_friction_off: vec![false; balls.len()],
            },
            balls: slots,
            pockets,
            params: *params,
            time: 0.0,
        }
    }

    /// Lets the resting balls sink into the soft cloth until they are still (their depth changes
    /// by less than [`SETTLED_DEPTH_CHANGE`] over [`SETTLE_CHECK`] steps, or `max_time` seconds
    /// pass). Returns the depth they sank, m.
    pub fn settle(&mut self, max_time: f64) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let depth = |w: &World| w.params.ball_radius - w.kinematics(0).pos.z;
        let checks = (max_time / (self.dt() * SETTLE_CHECK as f64)).ceil() as usize;
        let mut last = depth(self);
        for _ in 0..checks {
            for _ in 0..SETTLE_CHECK {
                self.step();
            }
            let now = depth(self);
            if (now - last).abs() < SETTLED_DEPTH_CHANGE {
                break;
            }
            last = now;
        }
        depth(self)
    }

    /// Gives every ball the state `states[i]` (`None`: out of play, pocketed) and sets the
    /// clock to `t`, s.
    pub fn place(&mut self, t: f64, states: &[Option<RapierBallState>]) {
        for (slot, k) in self.balls.iter_mut().zip(states) {
            let rb = &mut self.phys.bodies[slot.body];
            match k {
                Some(k) => {
                    slot.in_play = true;
                    rb.set_enabled(true);
                    rb.set_translation(to_glam(k.pos), true);
                    rb.set_linvel(to_glam(k.vel), true);
                    rb.set_angvel(to_glam(k.spin), true);
                    rb.reset_forces(true);
                    rb.reset_torques(true);
                }
                None => {
                    slot.in_play = false;
                    rb.set_enabled(false);
                }
            }
        }
        self.rules.cloth_friction_off.fill(false);
        self.time = t;
    }

    /// The time step, s.
    pub fn dt(&self) -> f64 {
        self.phys.integration_parameters.dt
    }

    /// Simulated time of the shot (as set by [`World::place`]), s.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Number of balls (in play or not).
    pub fn len(&self) -> usize {
        self.balls.len()
    }

    /// True when the world has no balls.
    pub fn is_empty(&self) -> bool {
        self.balls.is_empty()
    }

    /// True while ball `i` has not been pocketed.
    pub fn in_play(&self, i: usize) -> bool {
        self.balls[i].in_play
    }

    /// Ball `i`'s state.
    pub fn kinematics(&self, i: usize) -> RapierBallState {
        let rb = &self.phys.bodies[self.balls[i].body];
        RapierBallState {
            pos: from_glam(rb.translation()),
            vel: from_glam(rb.linvel()),
            spin: from_glam(rb.angvel()),
        }
    }

    /// Sets the external load on ball `i` for the next step.
    pub fn set_load(&mut self, i: usize, load: Load) {
        let rb = &mut self.phys.bodies[self.balls[i].body];
        rb.reset_forces(true);
        rb.reset_torques(true);
        rb.add_force(to_glam(load.force), true);
        rb.add_torque(to_glam(load.torque), true);
    }

    /// Turns the cloth's friction on ball `i` off (or back on) for the next step.
    pub fn set_cloth_friction_off(&mut self, i: usize, off: bool) {
        self.rules.cloth_friction_off[i] = off;
    }

    /// True when the cloth's friction on ball `i` is off for the next step.
    pub fn cloth_friction_off(&self, i: usize) -> bool {
        self.rules.cloth_friction_off[i]
    }

    /// Advances the world by one step.
    pub fn step(&mut self) {
        self.phys.step_with_events(&self.rules, &());
        self.time += self.dt();
    }

    /// Every contact of a ball in play that carried an impulse during the last step.
    pub fn touches(&self) -> Vec<Touch> {
        let mut out = Vec::new();
        for (i, slot) in self.balls.iter().enumerate() {
            if !slot.in_play {
                continue;
            }
            for pair in self.phys.narrow_phase.contact_pairs_with(slot.collider) {
                let other_handle = if pair.collider1 == slot.collider {
                    pair.collider2
                } else {
                    pair.collider1
                };
                let other = TablePart::decode(self.phys.colliders[other_handle].user_data);
                let mut normal = 0.0;
                let mut tangent = 0.0;
                for m in pair.solver_manifolds() {
                    for c in &m.points {
                        normal += c.data.impulse;
                        tangent += c.data.tangent_impulse.norm();
                    }
                }
                if normal > 0.0 {
                    out.push(Touch {
                        ball: i,
                        other,
                        normal_impulse: normal,
                        tangent_impulse: tangent,
                    });
                }
            }
        }
        out
    }

    /// The pocket ball `i` overlaps, if any.
    pub fn pocket_of(&self, i: usize) -> Option<usize> {
        let c = self.balls[i].collider;
        self.pockets.iter().position(|&p| {
            self.phys
                .narrow_phase
                .intersection_pair(c, p)
                .unwrap_or(false)
        })
    }

    /// Takes ball `i` out of play (it fell into a pocket).
    pub fn remove(&mut self, i: usize) {
        let slot = &mut self.balls[i];
        if slot.in_play {
            slot.in_play = false;
            self.phys.bodies[slot.body].set_enabled(false);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bodies_round_trip_through_user_data() {
        for b in [
            TablePart::Cloth,
            TablePart::Ball(3),
            TablePart::Cushion(17),
            TablePart::Jaw(11),
            TablePart::Pocket(5),
        ] {
            assert_eq!(TablePart::decode(b.encode()), b);
        }
    }
}
