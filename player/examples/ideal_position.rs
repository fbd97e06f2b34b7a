//! A bound on what position play can gain (issue 23): open-table visits in which, before every
//! stroke after the first, the cue ball is lifted and put down where the closed-form position
//! value ([`Valuer::from`]) is highest over the whole table (a 3 cm grid, clear of every ball
//! by 5 mm and off the pockets), as if every positional stroke had left it at the best place there is, without
//! error. The player then chooses and plays its stroke as usual under the noise. What it pots
//! from there is the pot success perfect position would give this player; the breaks are what
//! that success makes of a visit.
//!
//! With a spread σ > 0 the bound is the realistic one: the place is the best on average over
//! a normal spread of σ each way (3 × 3 Gauss–Hermite points, a point inside a ball counting
//! nothing, as the player's own valuer counts it), and the cue ball is put down at a normal
//! error of σ each way from it (seeded; redrawn while it would touch a ball or lie over a
//! pocket).
//!
//! With a file of distances (m, one a line) as well, the cue ball is put down at one of them
//! drawn at random, in a random direction, from that place: the player's own errors (the
//! distances its cue ball stopped from its planned ends, `examples/attempts.rs`) around the
//! best places.
//!
//! `cargo run --release -p snooker-player --example ideal_position -- FROM TO [EFFORT] [NOISE]
//! [SPREAD_M] [ERRORS_FILE]` writes one JSON line per visit (the open-table benchmark's
//! fields), layout k played with seed k as in `benches/open_table.rs`.

mod args;

use args::arg;
use snooker_engine::{BallKind, BallState, Vec3};
use snooker_planner::Noise;
use snooker_player::game::with_choices;
use snooker_player::value::object_positions;
use snooker_player::{Agent, Context, PlanKind, Player, Valuer, Watch, executed};
use snooker_rules::{Frame, Next};
use std::time::Instant;

/// Grid spacing for the cue ball's best place, m, and the clearance kept from other balls.
const STEP: f64 = 0.03;
const CLEAR: f64 = 0.005;

/// SplitMix64: the example's own seeded uniform numbers in (0, 1).
struct Mix(u64);
impl Mix {
    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        ((z >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn normal(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

/// `frame` with its cue ball moved to the best place on the table by `valuer`, on average over
/// a spread `sd` (m), and put down at a normal error `sd` from there.
fn ideal(frame: &Frame, valuer: &Valuer, sd: f64, errors: &[f64], rng: &mut Mix) -> Frame {
    let r = frame.params().ball_radius;
    let (l, w) = (frame.table().length, frame.table().width);
    let others = object_positions(frame);
    let contact = frame.params().cushion_contact_distance();
    let free = |q: Vec3| {
        frame
            .table()
            .placement_error(Vec3::new(q.x, q.y, 0.0), contact)
            .is_none()
            && others
                .iter()
                .all(|o| (o - q).xy().norm() >= 2.0 * r + CLEAR)
    };
    let mut best = (-1.0, None);
    let (nx, ny) = (
        ((l - 2.0 * r) / STEP) as usize,
        ((w - 2.0 * r) / STEP) as usize,
    );
    for i in 0..=nx {
        for j in 0..=ny {
            let p = Vec3::new(r + i as f64 * STEP, r + j as f64 * STEP, r);
            if !free(p) {
                continue;
            }
            let v = spread_value(frame, valuer, p, sd, &others);
            if v > best.0 {
                best = (v, Some(p));
            }
        }
    }
    let Some(target) = best.1 else {
        return frame.clone();
    };
    let mut p = target;
    for _ in 0..50 {
        let step = if errors.is_empty() {
            Vec3::new(sd * rng.normal(), sd * rng.normal(), 0.0)
        } else {
            let k = ((rng.uniform() * errors.len() as f64) as usize).min(errors.len() - 1);
            let angle = std::f64::consts::TAU * rng.uniform();
            errors[k] * Vec3::new(angle.cos(), angle.sin(), 0.0)
        };
        let q = target + step;
        let q = Vec3::new(q.x.clamp(r, l - r), q.y.clamp(r, w - r), r);
        if free(q) {
            p = q;
            break;
        }
    }
    let balls = frame
        .balls()
        .iter()
        .map(|b| {
            let mut b = b.clone();
            if b.kind == BallKind::Cue {
                b.state = BallState::at_rest(p.x, p.y, r);
            }
            b
        })
        .collect();
    Frame::new(
        frame.name(),
        frame.table().clone(),
        *frame.params(),
        *frame.models(),
        *frame.options(),
        balls,
        *frame.state(),
    )
    .expect("the cue ball moved to a clear place is a frame")
}

/// The mean of [`Valuer::from`] over a normal spread `sd` each way around `p`.
fn spread_value(frame: &Frame, valuer: &Valuer, p: Vec3, sd: f64, others: &[Vec3]) -> f64 {
    if sd <= 0.0 {
        return valuer.from(frame, p).0;
    }
    const Z: [f64; 3] = [-1.224_744_871_391_589, 0.0, 1.224_744_871_391_589];
    const W: [f64; 3] = [1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0];
    let r = frame.params().ball_radius;
    let mut total = 0.0;
    for (zx, wx) in Z.iter().zip(W) {
        for (zy, wy) in Z.iter().zip(W) {
            let q = p + Vec3::new(zx * sd, zy * sd, 0.0);
            if others.iter().any(|o| (o - q).xy().norm() < 2.0 * r) {
                continue;
            }
            total += wx * wy * valuer.from(frame, q).0;
        }
    }
    total
}

/// The distances in `path` (m, one a line), or why not.
fn read_errors(path: &str) -> Result<Vec<f64>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| e.to_string())?;
    let errors = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(i, l)| match l.trim().parse::<f64>() {
            Ok(d) if d.is_finite() && d >= 0.0 => Ok(d),
            _ => Err(format!("line {}: not a distance in metres: {l:?}", i + 1)),
        })
        .collect::<Result<Vec<f64>, String>>()?;
    if errors.is_empty() {
        return Err("no distances".into());
    }
    Ok(errors)
}

fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let from: u64 = arg(&a, 0, "first layout", 1);
    let to: u64 = arg(&a, 1, "last layout", from);
    let effort: u64 = arg(&a, 2, "effort", 4000);
    let k: f64 = arg(&a, 3, "noise multiple", 1.0);
    let sd: f64 = arg(&a, 4, "spread in metres", 0.0);
    if !(sd.is_finite() && sd >= 0.0 && k.is_finite() && k >= 0.0 && from <= to) {
        eprintln!("the spread and the noise multiple must be finite and >= 0, FROM <= TO");
        std::process::exit(2);
    }
    let errors: Vec<f64> = match a.get(5) {
        None => Vec::new(),
        Some(path) => match read_errors(path) {
            Ok(e) => e,
            Err(why) => {
                eprintln!("{path}: {why}");
                std::process::exit(2);
            }
        },
    };
    let noise = Noise::STANDARD.scaled(k);
    for seed in from..=to {
        let mut frame = snooker_player::layouts::open_table_in_hand(seed);
        let valuer = Valuer::new(&noise, frame.params());
        let mut rng = Mix(seed);
        let (mut points, mut att, mut pot, mut strokes) = (0u32, 0, 0, 0);
        let mut times = Vec::new();
        let mut cleared = false;
        let mut legal = true;
        for n in 1..=300u64 {
            let f = if frame.state().ball_in_hand {
                frame.clone()
            } else {
                ideal(&frame, &valuer, sd, &errors, &mut rng)
            };
            let ctx = Context {
                noise,
                seed,
                stroke: n,
                effort,
                watch: Watch::default(),
            };
            let start = Instant::now();
            let d = Player.choose(&f, &ctx).expect("a decision");
            times.push(start.elapsed().as_secs_f64());
            let chosen = with_choices(&f, &d).expect("the decision's frame");
            let ex = executed(&chosen, &d.strike, &noise, seed, n);
            let played = chosen.play(&ex).expect("a stroke");
            let v = &played.verdict;
            strokes += 1;
            points += v.points;
            legal &= v.legal();
            if d.plan.kind != PlanKind::Safety {
                att += 1;
                if v.legal() && v.potted.contains(&d.plan.pot) {
                    pot += 1;
                }
            }
            match chosen.next(v) {
                Next::Play(nf) if nf.state().to_play == frame.state().to_play => frame = *nf,
                Next::Over { .. } => {
                    cleared = legal;
                    break;
                }
                _ => break,
            }
        }
        println!(
            "{{\"noise\": {k}, \"seed\": {seed}, \"effort\": {effort}, \"break\": {points}, \"cleared\": {cleared}, \"strokes\": {strokes}, \"attempts\": {att}, \"pots\": {pot}, \"spread\": {sd}, \"errors\": {}, \"decision_times\": {times:?}}}",
            errors.len()
        );
    }
}
