//! Plays frames of random legal-looking strokes (aimed at a ball on, a little off the full-ball
//! line, at a random speed; a random legal nomination; the cue ball in hand placed near the
//! middle of the D) from seeded open tables, and prints what happened: how many frames ended
//! within the cap of strokes, strokes, fouls by reason, free balls, respots, and the time spent
//! simulating and judging. `cargo run --profile ci -p snooker-rules --example random_frames [FRAMES] [CAP]`.

use snooker_engine::rng::Rng;
use snooker_engine::{Cue, Vec3, simulate};
use snooker_rules::{Frame, Next, On};
use std::collections::BTreeMap;
use std::time::{Duration, Instant};

fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let (frames, cap) = (
        args.first().copied().unwrap_or(50),
        args.get(1).copied().unwrap_or(300),
    );
    let mut rng = Rng(0x5eed_0026);
    let (mut ended, mut strokes, mut free_balls, mut respots) = (0, 0, 0, 0);
    let mut fouls: BTreeMap<&str, usize> = BTreeMap::new();
    let (mut sim_time, mut judge_time) = (Duration::ZERO, Duration::ZERO);
    for n in 0..frames {
        let mut f = Frame::open_table(15, n as u64);
        for _ in 0..cap {
            let s = *f.state();
            if s.ball_in_hand && f.cue_index().is_none() {
                let d = f.the_d();
                let p = f
                    .nearest_placement([d.centre.x - 0.15, d.centre.y])
                    .unwrap();
                f = f.with_cue_ball_at(p).unwrap();
            }
            let noms = f.legal_nominations();
            if (s.on == On::Colour || s.free_ball) && s.nominated.is_none() {
                let k = rng.uniform(0.0, noms.len() as f64) as usize;
                f = f
                    .with_nomination(Some(noms[k.min(noms.len() - 1)]))
                    .unwrap();
            }
            let on = f.balls_on();
            let k = (rng.uniform(0.0, on.len() as f64) as usize).min(on.len() - 1);
            let target = f.balls()[on[k]].state.pos;
            let cue = f.balls()[f.cue_index().unwrap()].state.pos;
            let d: Vec3 = target - cue;
            let strike = Cue {
                speed: rng.uniform(0.5, 5.0),
                aim: d.y.atan2(d.x) + rng.uniform(-0.04, 0.04),
                offset: [0.0, rng.uniform(-0.008, 0.008)],
                elevation: 0.0,
            };
            let setup = f.setup(&strike).unwrap();
            let t = Instant::now();
            let shot = simulate(&setup, f.options()).unwrap();
            sim_time += t.elapsed();
            let t = Instant::now();
            let v = f.judge(&shot).unwrap();
            judge_time += t.elapsed();
            strokes += 1;
            if let Some(foul) = &v.foul {
                *fouls.entry(foul.reason.name()).or_default() += 1;
            }
            free_balls += usize::from(v.next.is_some_and(|n| n.free_ball));
            respots += v.respotted.len();
            match f.next(&v) {
                Next::Play(next) => f = *next,
                Next::Over { .. } => {
                    ended += 1;
                    break;
                }
            }
        }
    }
    println!("{frames} frames from seeded open tables, at most {cap} strokes each");
    println!(
        "ended: {ended}; strokes: {strokes} ({:.1} a frame)",
        strokes as f64 / frames as f64
    );
    println!("fouls: {fouls:?}");
    println!("free balls awarded: {free_balls}; colours respotted: {respots}");
    println!(
        "simulation {:.1} us a stroke, judging {:.2} us a stroke",
        sim_time.as_secs_f64() * 1e6 / strokes as f64,
        judge_time.as_secs_f64() * 1e6 / strokes as f64
    );
}
