//! Random scenes of every kind a user can write, and hostile ones: the cue ball struck at any
//! speed, offset and elevation; balls placed at random and where trouble lives (touching,
//! frozen to a cushion, in the jaws, in clusters); balls given velocities and spins, some in
//! the air; parameters anywhere in their documented ranges; both impact models; Newton's
//! cradles; the break-off; and scenes with bad input.

use rand::RngExt;
use rand::rngs::ChaCha8Rng;
use snooker_engine::ball::ROLLING_SHARE;
use snooker_engine::cue::{self, Cue, MAX_CUE_SPEED, MAX_ELEVATION};
use snooker_engine::params::{Bound, MAX_TILT_PER_MU_ROLL, NOSE_HEIGHT_PER_RADIUS, PARAMS};
use snooker_engine::{BallState, Params, SnookerDims, Table, Vec3};
use snooker_scene::write::{BallText, CueText, SceneText, num};
use std::f64::consts::{PI, TAU};

/// What kind of scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Kind {
    /// 2-22 balls at random places, the cue ball struck.
    Strike,
    /// Balls touching, frozen to cushions, in the jaws, in clusters; the cue ball struck.
    Adversarial,
    /// Balls given velocities and spins directly.
    GivenMotion,
    /// Some balls start in the air.
    Airborne,
    /// Parameters anywhere in their documented ranges, either impact model.
    Parameters,
    /// A line of touching balls struck end on.
    Cradle,
    /// The break-off layout, struck at random.
    BreakOff,
    /// Bad input: must be rejected with a message, never crash.
    Hostile,
}

impl Kind {
    /// Every kind, in report order.
    pub const ALL: [Kind; 8] = [
        Kind::Strike,
        Kind::Adversarial,
        Kind::GivenMotion,
        Kind::Airborne,
        Kind::Parameters,
        Kind::Cradle,
        Kind::BreakOff,
        Kind::Hostile,
    ];

    /// The kind of scene `k`: in every 64 scenes, 10 strikes, 10 adversarial, 8 with given
    /// motion, 8 airborne, 10 with parameters anywhere in their ranges, 8 break-offs, 8
    /// hostile and 2 Newton's cradles (the costliest: a cradle of n balls takes about n^3 / 20
    /// impacts at one instant).
    pub fn of_scene(k: u64) -> Kind {
        const SHARES: [(Kind, u64); 8] = [
            (Kind::Strike, 10),
            (Kind::Adversarial, 10),
            (Kind::GivenMotion, 8),
            (Kind::Airborne, 8),
            (Kind::Parameters, 10),
            (Kind::BreakOff, 8),
            (Kind::Hostile, 8),
            (Kind::Cradle, 2),
        ];
        let mut r = k % 64;
        for (kind, n) in SHARES {
            if r < n {
                return kind;
            }
            r -= n;
        }
        Kind::Strike
    }

    /// Its name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Strike => "strike",
            Kind::Adversarial => "adversarial",
            Kind::GivenMotion => "given-motion",
            Kind::Airborne => "airborne",
            Kind::Parameters => "parameters",
            Kind::Cradle => "cradle",
            Kind::BreakOff => "break-off",
            Kind::Hostile => "hostile",
        }
    }
}

/// A generated scene and what is expected of it.
#[derive(Clone, Debug)]
pub struct Generated {
    /// Its kind.
    pub kind: Kind,
    /// The scene file.
    pub text: String,
    /// True when the parameters are those of a physical cloth (see [`physical_cloth`]): the
    /// shot must then end with every ball at rest, pocketed or off the table.
    pub physical: bool,
}

/// Standard gravity, m/s^2: the cloth's decelerations below are judged against a ball on the
/// thesis's table (its frictions measured there, thesis §5.1).
const G0: f64 = 9.81;

/// Why a cloth is not a physical one, if it is not: a sliding deceleration below 0.05 g0, a
/// rolling one below 0.005 g0, sidespin decay below 5 rad/s^2 (the thesis measured 0.21 g0,
/// 0.0128 g0 and 22, §5.1, §5.3; a low `g` lowers the first two with it), or a bed tilt and a
/// nap that together push a rolling ball with more than half its rolling resistance (a ball
/// then keeps pressing into a cushion or a cluster, meeting it again and again, for as long as
/// it rolls). On such a cloth a ball may still be moving after `max_time` or run into the
/// event cap: a physical outcome, not a failure.
pub fn unphysical_cloth(p: &Params) -> Option<&'static str> {
    let push = ROLLING_SHARE * (p.g * p.tilt() + p.nap_drift.abs());
    // With a speed scale, friction falls towards mu_slide_low as the slip stops.
    let least_slide = if p.slide_speed_scale > 0.0 {
        p.mu_slide.min(p.mu_slide_low)
    } else {
        p.mu_slide
    };
    if least_slide * p.g < 0.05 * G0 {
        Some("sliding deceleration < 0.05 g0")
    } else if p.mu_roll * p.g < 0.005 * G0 {
        Some("rolling deceleration < 0.005 g0")
    } else if p.sidespin_decel < 5.0 {
        Some("sidespin decay < 5 rad/s^2")
    } else if push > 0.5 * p.mu_roll * p.g {
        Some("tilt and nap > half the rolling resistance")
    } else {
        None
    }
}

/// True for the frictions of a real cloth ([`unphysical_cloth`]): every shot on it must end
/// with every ball at rest, pocketed or off the table.
pub fn physical_cloth(p: &Params) -> bool {
    unphysical_cloth(p).is_none()
}

struct Gen<'a> {
    rng: &'a mut ChaCha8Rng,
    p: Params,
    table: Table,
    scene: SceneText,
    /// Centres placed so far.
    placed: Vec<Vec3>,
}

impl Gen<'_> {
    fn u(&mut self, a: f64, b: f64) -> f64 {
        self.rng.random_range(a..b)
    }

    fn chance(&mut self, p: f64) -> bool {
        self.rng.random_bool(p)
    }

    fn r(&self) -> f64 {
        self.p.ball_radius
    }

    fn contact(&self) -> f64 {
        self.p.cushion_contact_distance()
    }

    /// True if a ball can stand at `pos`: on the cloth, clear of jaws and pockets, no overlap.
    fn free(&self, pos: Vec3) -> bool {
        if self.table.placement_error(pos, self.contact()).is_some() {
            return false;
        }
        let two_r = 2.0 * self.r();
        self.placed
            .iter()
            .all(|q| (Vec3::new(pos.x, pos.y, 0.0) - q).norm() >= two_r)
    }

    fn add(&mut self, id: String, pos: Vec3) {
        self.placed.push(Vec3::new(pos.x, pos.y, 0.0));
        self.scene.balls.push(BallText {
            id,
            pos: [pos.x, pos.y],
            vel: None,
            spin: None,
        });
    }

    fn next_id(&self) -> String {
        if self.scene.balls.is_empty() {
            return "cue".into();
        }
        const COLOURS: [&str; 6] = ["yellow", "green", "brown", "blue", "pink", "black"];
        let n = self.scene.balls.len();
        if n <= 6 && n.is_multiple_of(2) {
            COLOURS[n / 2 - 1].to_string()
        } else {
            format!("red{n}")
        }
    }

    fn extent(&self) -> (f64, f64) {
        if self.scene.open_table {
            (3.0, 1.5)
        } else {
            (self.table.length, self.table.width)
        }
    }

    /// A uniformly random free spot (None after many tries).
    fn random_spot(&mut self) -> Option<Vec3> {
        let c = self.contact();
        let (l, w) = self.extent();
        for _ in 0..200 {
            let pos = Vec3::new(self.u(c, l - c), self.u(c, w - c), 0.0);
            if self.free(pos) {
                return Some(pos);
            }
        }
        None
    }

    /// A spot touching an already placed ball.
    fn touching_spot(&mut self) -> Option<Vec3> {
        if self.placed.is_empty() {
            return self.random_spot();
        }
        for _ in 0..50 {
            let k = self.rng.random_range(0..self.placed.len());
            let a = self.u(0.0, TAU);
            let pos = self.placed[k] + 2.0 * self.r() * Vec3::new(a.cos(), a.sin(), 0.0);
            if self.free(pos) {
                return Some(pos);
            }
        }
        None
    }

    /// A spot frozen to a cushion nose.
    fn frozen_spot(&mut self) -> Option<Vec3> {
        let c = self.contact();
        let (l, w) = (self.table.length, self.table.width);
        for _ in 0..50 {
            let pos = match self.rng.random_range(0..4) {
                0 => Vec3::new(c, self.u(c, w - c), 0.0),
                1 => Vec3::new(l - c, self.u(c, w - c), 0.0),
                2 => Vec3::new(self.u(c, l - c), c, 0.0),
                _ => Vec3::new(self.u(c, l - c), w - c, 0.0),
            };
            if self.free(pos) {
                return Some(pos);
            }
        }
        None
    }

    /// A spot near a pocket's jaws.
    fn jaw_spot(&mut self) -> Option<Vec3> {
        for _ in 0..200 {
            let k = self.rng.random_range(0..self.table.pockets.len());
            let mouth = self.table.pockets[k].mouth;
            let spread = 3.0 * self.r();
            let pos = mouth + Vec3::new(self.u(-spread, spread), self.u(-spread, spread), 0.0);
            if self.free(pos) {
                return Some(pos);
            }
        }
        None
    }

    fn place(&mut self, n: usize, adversarial: bool) {
        for _ in 0..n {
            let spot = if adversarial {
                match self.rng.random_range(0..4) {
                    0 => self.touching_spot(),
                    1 => self.frozen_spot(),
                    2 => self.jaw_spot(),
                    _ => self.random_spot(),
                }
            } else {
                self.random_spot()
            };
            if let Some(pos) = spot {
                let id = self.next_id();
                self.add(id, pos);
            }
        }
    }

    /// A cue strike on the first ball that the engine accepts (no miscue).
    fn strike(&mut self) {
        let Some(first) = self.scene.balls.first().cloned() else {
            return;
        };
        let state = BallState::at_rest(first.pos[0], first.pos[1], self.r());
        for _ in 0..100 {
            let speed = if self.chance(0.5) {
                self.u(0.1, 4.0)
            } else {
                self.u(0.1, MAX_CUE_SPEED)
            };
            let elevation = match self.rng.random_range(0..3) {
                0 => 0.0,
                1 => self.u(0.0, 0.3),
                _ => self.u(0.0, MAX_ELEVATION),
            };
            let reach = self.p.miscue_limit * self.r();
            let (a, d) = (self.u(0.0, TAU), reach * self.u(0.0, 1.0f64).sqrt());
            let c = Cue {
                speed,
                aim: self.u(-PI, PI),
                offset: [d * a.cos(), d * a.sin()],
                elevation,
            };
            if cue::strike(&state, &c, &self.p).is_ok() {
                self.scene.cue = Some((
                    first.id.clone(),
                    CueText {
                        speed: c.speed,
                        aim: c.aim,
                        offset: c.offset,
                        elevation: c.elevation,
                    },
                ));
                return;
            }
        }
    }

    /// Random velocities and spins on some balls (not a ball about to be struck: the strike
    /// adds to its motion); `airborne` lifts some of them.
    fn motion(&mut self, airborne: bool) {
        let r = self.r();
        for i in 0..self.scene.balls.len() {
            if self
                .scene
                .cue
                .as_ref()
                .is_some_and(|(id, _)| *id == self.scene.balls[i].id)
            {
                continue;
            }
            if !self.chance(0.6) {
                continue;
            }
            let speed = if self.chance(0.7) {
                self.u(0.0, 5.0)
            } else {
                self.u(0.0, 25.0)
            };
            let a = self.u(0.0, TAU);
            let vz = if airborne && self.chance(0.6) {
                self.u(0.0, 4.0)
            } else {
                0.0
            };
            let spin_scale = if self.chance(0.5) { 2.0 } else { 60.0 };
            let w = Vec3::new(self.u(-1.0, 1.0), self.u(-1.0, 1.0), self.u(-1.0, 1.0));
            let w = w * (spin_scale / r).min(99.0 / r) / 3f64.sqrt();
            let b = &mut self.scene.balls[i];
            b.vel = Some([speed * a.cos(), speed * a.sin(), vz]);
            b.spin = Some([w.x, w.y, w.z]);
        }
    }

    /// Parameters anywhere in their ranges (a few at a time), keeping the conditions between
    /// them; sometimes other impact models (frictionless, and the compliant cushion).
    fn parameters(&mut self) {
        let mut p = Params::default();
        let mut set: Vec<(&'static str, f64)> = Vec::new();
        let count = self.rng.random_range(1..6);
        for _ in 0..count {
            let info = PARAMS[self.rng.random_range(0..PARAMS.len())];
            let (_, hi) = info.range.ends();
            let lo = match info.range.lo {
                Bound::Inclusive(x) => x,
                Bound::Exclusive(x) => x + 1e-9 * (hi - x),
            };
            let hi = match info.range.hi {
                Bound::Inclusive(x) => x,
                Bound::Exclusive(x) => x - 1e-9 * (x - lo),
            };
            let v = match self.rng.random_range(0..4) {
                0 => lo,
                1 => hi,
                _ => self.u(0.0, 1.0) * (hi - lo) + lo,
            };
            set.retain(|(n, _)| *n != info.name);
            set.push((info.name, v));
        }
        for &(n, v) in &set {
            if let Some(slot) = p.field_mut(n) {
                *slot = v;
            }
        }
        // The conditions between parameters, as the engine states them.
        let radius_given = set.iter().any(|(n, _)| *n == "ball_radius");
        let height_given = set.iter().any(|(n, _)| *n == "cushion_height");
        if radius_given && !height_given {
            p.cushion_height = NOSE_HEIGHT_PER_RADIUS * p.ball_radius;
        }
        if height_given || radius_given {
            let h = p.ball_radius * self.u(1.05, 1.95);
            p.cushion_height = h;
            set.retain(|(n, _)| *n != "cushion_height");
            set.push(("cushion_height", h));
        }
        if p.slide_speed_scale > 0.0 && p.mu_slide_low > p.mu_slide {
            p.mu_slide_low = p.mu_slide;
            set.retain(|(n, _)| *n != "mu_slide_low");
            set.push(("mu_slide_low", p.mu_slide));
        }
        if p.tilt_rolls_resting_balls() {
            let k = self.u(0.0, 0.99) * MAX_TILT_PER_MU_ROLL * p.mu_roll / p.tilt();
            p.slope_x *= k;
            p.slope_y *= k;
            set.retain(|(n, _)| *n != "slope_x" && *n != "slope_y");
            set.push(("slope_x", p.slope_x));
            set.push(("slope_y", p.slope_y));
        }
        if p.validate().is_ok() {
            self.p = p;
            self.scene.params = set;
        }
        if self.chance(0.3) {
            let pick = |g: &mut Self| {
                if g.chance(0.5) {
                    "frictionless"
                } else {
                    "mathavan"
                }
            };
            // The cushion also as the compliant one (issue 25).
            let cushion = match self.rng.random_range(0..3) {
                0 => "frictionless",
                1 => "mathavan",
                _ => "compliant",
            };
            let models = (pick(self), cushion);
            self.scene.models = Some(models);
        }
    }
}

/// Generates scene `kind` from `rng`.
pub fn generate(kind: Kind, rng: &mut ChaCha8Rng) -> Generated {
    let mut g = Gen {
        rng,
        p: Params::default(),
        table: Table::snooker(&SnookerDims::default()),
        scene: SceneText::default(),
        placed: Vec::new(),
    };
    match kind {
        Kind::Strike => {
            let n = g.rng.random_range(2..=22);
            g.place(n, false);
            g.strike();
        }
        Kind::Adversarial => {
            let n = g.rng.random_range(2..=22);
            g.place(n, true);
            g.strike();
        }
        Kind::GivenMotion | Kind::Airborne => {
            let n = g.rng.random_range(1..=22);
            let adversarial = g.chance(0.5);
            g.place(n, adversarial);
            if g.chance(0.3) {
                g.strike();
            }
            g.motion(kind == Kind::Airborne);
        }
        Kind::Parameters => {
            g.parameters();
            let n = g.rng.random_range(1..=22);
            let adversarial = g.chance(0.5);
            g.place(n, adversarial);
            if g.chance(0.7) {
                g.strike();
            } else {
                let airborne = g.chance(0.3);
                g.motion(airborne);
            }
        }
        Kind::Cradle => {
            g.scene.open_table = true;
            g.table = Table::open();
            // Mostly short lines; one in fifty as long as a full table's length (68 balls) and
            // beyond (a line of n takes about n^3 / 20 impacts: one of 80 costs as much as a
            // thousand other scenes; scene/tests/regressions.rs runs 60 and 120).
            let n = if g.chance(0.02) {
                g.rng.random_range(41..=80)
            } else {
                g.rng.random_range(2..=40)
            };
            let r = g.r();
            for k in 0..n {
                let id = g.next_id();
                g.add(id, Vec3::new(k as f64 * 2.0 * r, 0.0, 0.0));
            }
            let speed = g.u(0.1, 10.0);
            g.scene.cue = Some((
                "cue".into(),
                CueText {
                    speed,
                    aim: 0.0,
                    offset: [0.0, 0.0],
                    elevation: 0.0,
                },
            ));
        }
        Kind::BreakOff => {
            g.scene.layout = Some("break-off".into());
            let dims = SnookerDims::default();
            let brown = dims.spot("brown").unwrap_or_default();
            // The layout's cue ball; the strike is checked against it.
            g.scene.balls.push(BallText {
                id: "cue".into(),
                pos: [brown.x, brown.y - 0.5 * dims.d_radius],
                vel: None,
                spin: None,
            });
            g.strike();
            g.scene.balls.clear();
        }
        Kind::Hostile => {
            let base = generate(Kind::Strike, g.rng);
            let text = corrupt(&base.text, g.rng);
            return Generated {
                kind,
                text,
                physical: true,
            };
        }
    }
    let physical = physical_cloth(&g.p);
    Generated {
        kind,
        text: g.scene.to_toml(),
        physical,
    }
}

/// One corruption of a valid scene's text: bad arrays, bad numbers, unknown keys, duplicate
/// ids, impossible places, wrong types, truncation.
fn corrupt(text: &str, rng: &mut ChaCha8Rng) -> String {
    let bad_numbers = ["nan", "inf", "-inf", "1e308", "-1e308", "-1", "0", "1e-308"];
    let bad = bad_numbers[rng.random_range(0..bad_numbers.len())];
    let lines: Vec<&str> = text.lines().collect();
    match rng.random_range(0..10) {
        0 => text.replacen("pos = [", "pos = [0.5, ", 1),
        1 => text.replacen("offset = [", "offset = [0.0, ", 1),
        2 => format!(
            "[params]\n{} = {bad}\n{text}",
            PARAMS[rng.random_range(0..PARAMS.len())].name
        ),
        3 => text.replacen("speed = ", &format!("speed = {bad} #"), 1),
        4 => format!("{text}[[balls]]\nid = \"cue\"\npos = [1.0, 1.0]\n"),
        5 => format!(
            "{text}[[balls]]\nid = \"far\"\npos = [{}, 0.5]\n",
            num(10.0)
        ),
        6 => format!("{text}[[balls]]\nid = \"x\"\npos = \"here\"\nvel = [{bad}, 0, 0]\n"),
        7 => format!("unknown_key = 1\n{text}"),
        8 => {
            let cut = rng.random_range(0..text.len().max(1));
            let mut end = cut;
            while !text.is_char_boundary(end) {
                end -= 1;
            }
            text[..end].to_string()
        }
        _ => {
            let k = rng.random_range(0..lines.len().max(1));
            let mut l: Vec<String> = lines.iter().map(|s| s.to_string()).collect();
            if let Some(line) = l.get_mut(k)
                && let Some((key, _)) = line.clone().split_once(" = ")
            {
                *line = format!("{key} = {bad}");
            }
            l.join("\n") + "\n"
        }
    }
}
