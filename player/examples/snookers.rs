//! How the player plays when a direct stroke fouls: random snookers and touching balls.
//!
//! Two classes of seeded positions, `N` of each:
//! - `snookered`: the closing colours from one drawn at random to the black scattered over the
//!   table with the cue ball, kept when the cue ball is snookered on the colour on (WPBSA
//!   Section 2 Rule 17; `snooker_rules::snookered`) and no straight path meets any of it;
//! - `touching`: the closing colours scattered the same way, the cue ball laid against the
//!   colour on at a random angle (Section 3 Rule 8: it may not be moved; played away from, it
//!   counts as hit).
//!
//! For each, the player's decision at the standard noise and the default effort: whether its
//! strike is legal played as meant and as executed (the noise drawn as `snooker play` draws
//! it), the kind of stroke and the cushions it goes by. One JSON line per position, then a
//! summary per class on standard error.
//!
//! ```text
//! cargo run --release -p snooker-player --example snookers -- 100 > snookers.jsonl
//! ```

use snooker_engine::{Ball, BallKind, BallState, SnookerDims, Vec3};
use snooker_planner::Noise;
use snooker_player::game::{DEFAULT_EFFORT, executed, with_choices};
use snooker_player::{Agent, Context, Player};
use snooker_rules::{Colour, Frame, FrameState, On, snookered};

/// SplitMix64: the positions' own seeded stream (no dependency for a few uniform draws).
struct Draw(u64);

impl Draw {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        (z ^ (z >> 31)) as f64 / u64::MAX as f64
    }
}

const KINDS: [BallKind; 6] = [
    BallKind::Yellow,
    BallKind::Green,
    BallKind::Brown,
    BallKind::Blue,
    BallKind::Pink,
    BallKind::Black,
];

/// A point of the cloth at least 5 cm from the cushions, clear of `balls` by 2 mm.
fn clear_point(d: &mut Draw, dims: &SnookerDims, balls: &[Ball], r: f64) -> Option<Vec3> {
    for _ in 0..1000 {
        let p = Vec3::new(
            0.05 + d.next() * (dims.length - 0.1),
            0.05 + d.next() * (dims.width - 0.1),
            r,
        );
        if balls
            .iter()
            .all(|b| (b.state.pos - p).xy().norm() > 2.0 * r + 0.002)
        {
            return Some(p);
        }
    }
    None
}

/// True when no straight path of the cue ball from `c` meets the ball at `o` before another
/// (41 contacts across its width): a full snooker, not only its edges hidden.
fn hidden(c: Vec3, o: Vec3, others: &[Vec3], r: f64) -> bool {
    let flat = |v: Vec3| Vec3::new(v.x, v.y, 0.0);
    let to = flat(o - c);
    let dist = to.norm();
    (-20..=20).all(|k| {
        let off = (f64::from(k) / 20.0 * 0.999 * 2.0 * r / dist).asin();
        let a = to.y.atan2(to.x) + off;
        let u = Vec3::new(a.cos(), a.sin(), 0.0);
        // How far the cue ball's centre runs along u before it meets the ball on.
        let along = to.dot(&u);
        let across2 = to.norm_squared() - along * along;
        let reach = along - (4.0 * r * r - across2).max(0.0).sqrt();
        others.iter().any(|&q| {
            let w = flat(q - c);
            let t = w.dot(&u).clamp(0.0, reach);
            (w - t * u).norm() < 2.0 * r
        })
    })
}

/// The closing colours from one drawn at random to the black, scattered over the cloth; the
/// first is the colour on.
fn scatter(d: &mut Draw, r: f64) -> Option<(usize, Vec<Ball>)> {
    let dims = SnookerDims::default();
    let first = (d.next() * 5.999) as usize;
    let mut balls: Vec<Ball> = Vec::new();
    for (k, kind) in KINDS.iter().enumerate().skip(first) {
        let p = clear_point(d, &dims, &balls, r)?;
        balls.push(Ball {
            id: Colour::ALL[k].name().to_string(),
            kind: *kind,
            state: BallState::at_rest(p.x, p.y, r),
        });
    }
    Some((first, balls))
}

/// The frame of `balls` with the cue ball at `c`, colour `first` on, player 0 to play.
fn closing(template: &Frame, first: usize, mut balls: Vec<Ball>, c: Vec3) -> Option<Frame> {
    let r = template.params().ball_radius;
    balls.push(Ball {
        id: "cue".into(),
        kind: BallKind::Cue,
        state: BallState::at_rest(c.x, c.y, r),
    });
    let state = FrameState {
        on: On::Closing(Colour::ALL[first]),
        ball_in_hand: false,
        ..FrameState::start(0)
    };
    Frame::new(
        "snookers",
        template.table().clone(),
        *template.params(),
        *template.models(),
        *template.options(),
        balls,
        state,
    )
    .ok()
}

/// A snookered position in the closing colours, if the draw gives one.
fn snookered_position(seed: u64, template: &Frame) -> Option<Frame> {
    let mut d = Draw(seed);
    let r = template.params().ball_radius;
    let (first, balls) = scatter(&mut d, r)?;
    let c = clear_point(&mut d, &SnookerDims::default(), &balls, r)?;
    let on = [balls[0].state.pos];
    let not_on: Vec<Vec3> = balls[1..].iter().map(|b| b.state.pos).collect();
    if !snookered::is_snookered(c, &on, &not_on, &[], r) || !hidden(c, on[0], &not_on, r) {
        return None;
    }
    closing(template, first, balls, c)
}

/// The closing colours scattered as for a snooker, the cue ball laid against the colour on at
/// a random angle, if the draw leaves it clear.
fn touching_position(seed: u64, template: &Frame) -> Option<Frame> {
    let mut d = Draw(seed);
    let dims = SnookerDims::default();
    let r = template.params().ball_radius;
    let (first, balls) = scatter(&mut d, r)?;
    let a = d.next() * std::f64::consts::TAU;
    let c = balls[0].state.pos + 2.0 * r * Vec3::new(a.cos(), a.sin(), 0.0);
    let inside = c.x > 0.05 && c.y > 0.05 && c.x < dims.length - 0.05 && c.y < dims.width - 0.05;
    let clear = balls[1..]
        .iter()
        .all(|b| (b.state.pos - c).xy().norm() > 2.0 * r + 0.002);
    if !inside || !clear {
        return None;
    }
    closing(template, first, balls, c)
}

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .map_or(100, |a| a.parse().expect("N: positions per class"));
    let template = snooker_player::layouts::open_table_in_hand(1);
    for class in ["snookered", "touching"] {
        let (mut found, mut meant, mut played, mut cushions) = (0, 0, 0, [0usize; 3]);
        let mut seed = 0u64;
        while found < n {
            seed += 1;
            let frame = match class {
                "snookered" => snookered_position(seed, &template),
                _ => touching_position(seed, &template),
            };
            let Some(frame) = frame else { continue };

            found += 1;
            let ctx = Context {
                noise: Noise::STANDARD,
                seed,
                stroke: 1,
                effort: DEFAULT_EFFORT,
                watch: Default::default(),
            };
            let d = Player.choose(&frame, &ctx).expect("a decision");
            let chosen = with_choices(&frame, &d).expect("the decision's choices");
            let as_meant = chosen.play(&d.strike).expect("played").verdict;
            let strike = executed(&chosen, &d.strike, &ctx.noise, seed, 1);
            let as_played = chosen.play(&strike).expect("played").verdict;
            meant += usize::from(as_meant.legal());
            played += usize::from(as_played.legal());
            cushions[d.plan.via.len().min(2)] += usize::from(d.plan.kind.name() == "safety");
            println!(
                "{}",
                serde_json::json!({
                    "class": class,
                    "seed": seed,
                    "kind": d.plan.kind.name(),
                    "ball": d.plan.ball,
                    "via": d.plan.via,
                    "legal_as_meant": as_meant.legal(),
                    "legal_as_played": as_played.legal(),
                    "foul": as_played.foul.as_ref().map(|f| f.reason.to_string()),
                })
            );
        }
        eprintln!(
            "{class}: {n} positions; legal as meant {meant}, as played {played}; \
             safeties direct {}, off one cushion {}, off two {}",
            cushions[0], cushions[1], cushions[2]
        );
    }
}
