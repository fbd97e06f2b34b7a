//! Which part of the execution noise moves the cue ball's end (issue 23): the player's
//! potting strokes of open-table visits replayed with one component of the standard noise at
//! a time (aim, elevation, speed, side, height) and with all of them, each N times, and the
//! distance from where the stroke played as meant leaves the cue ball measured. The bound of
//! `examples/ideal_position.rs` puts the shortfall in that distance; this says where it
//! comes from.
//!
//! `cargo run --release -p snooker-player --example end_spread -- FROM TO [N]` (layouts
//! FROM..=TO played as in `benches/open_table.rs`; N draws per component and stroke, default
//! 24) prints per component the median and the 90th percentile of the distances, the share of
//! draws whose cue ball met a ball it did not meet played as meant, and the share of draws
//! that still potted the ball.

mod args;

use args::arg;
use snooker_engine::{EventKind, Shot, Vec3};
use snooker_planner::{Noise, rng_for};
use snooker_player::{PlanKind, PlayOptions, Player, play};
use snooker_rules::Frame;

/// The cue ball's end in `shot` and the balls it met after its first contact; None when it
/// left the table.
fn cue_end(frame: &Frame, shot: &Shot) -> Option<(Vec3, Vec<usize>)> {
    let cue = frame.cue_index()?;
    let track = &shot.tracks[cue];
    let end = track.state_at(shot.duration, &shot.params).pos;
    let mut met: Vec<usize> = shot
        .events
        .iter()
        .filter(|e| e.kind == EventKind::BallBall && e.balls.contains(&cue))
        .filter_map(|e| e.balls.iter().copied().find(|&b| b != cue))
        .skip(1)
        .collect();
    met.sort_unstable();
    met.dedup();
    Some((end, met))
}

fn percentile(v: &mut [f64], p: f64) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[((v.len() - 1) as f64 * p).round() as usize]
}

fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let from: u64 = arg(&a, 0, "first layout", 1);
    let to: u64 = arg(&a, 1, "last layout", from);
    let n: u64 = arg(&a, 2, "draws", 24);
    let s = Noise::STANDARD;
    let zero = Noise::STANDARD.scaled(0.0);
    let parts: [(&str, Noise); 6] = [
        ("aim", Noise { aim: s.aim, ..zero }),
        (
            "elevation",
            Noise {
                elevation: s.elevation,
                ..zero
            },
        ),
        (
            "speed",
            Noise {
                speed: s.speed,
                ..zero
            },
        ),
        (
            "side",
            Noise {
                side: s.side,
                ..zero
            },
        ),
        (
            "height",
            Noise {
                height: s.height,
                ..zero
            },
        ),
        ("all", s),
    ];
    // Per component: distances, draws meeting a new ball, draws potting, draws.
    let mut dist: Vec<Vec<f64>> = vec![Vec::new(); parts.len()];
    let mut cannon = vec![0u64; parts.len()];
    let mut potted = vec![0u64; parts.len()];
    let mut draws = vec![0u64; parts.len()];
    let mut strokes = 0;
    for seed in from..=to {
        let frame = snooker_player::layouts::open_table_in_hand(seed);
        let opts = PlayOptions {
            seed,
            ..PlayOptions::default()
        };
        let game = play(&frame, [&Player, &Player], &opts, |_| {}).expect("a visit");
        for rec in &game.strokes {
            if rec.decision.plan.kind == PlanKind::Safety {
                continue;
            }
            let f = &rec.frame;
            let Ok(meant) = f.play(&rec.decision.strike) else {
                continue;
            };
            let Some((end, met)) = cue_end(f, &meant.shot) else {
                continue;
            };
            let Some(ci) = f.cue_index() else {
                continue;
            };
            strokes += 1;
            let ball = f.balls()[ci].state;
            for (k, (_, noise)) in parts.iter().enumerate() {
                for d in 0..n {
                    let mut rng = rng_for(seed, &[rec.number, 0xe5d, k as u64, d]);
                    let cue = noise.apply(&rec.decision.strike, &ball, f.params(), &mut rng);
                    let Ok(p) = f.play(&cue) else {
                        continue;
                    };
                    draws[k] += 1;
                    if p.verdict.legal() && p.verdict.potted.contains(&rec.decision.plan.pot) {
                        potted[k] += 1;
                    }
                    match cue_end(f, &p.shot) {
                        Some((e, m)) if !p.verdict.cue_ball_potted => {
                            dist[k].push((e - end).xy().norm());
                            if m.iter().any(|b| !met.contains(b)) {
                                cannon[k] += 1;
                            }
                        }
                        _ => {}
                    }
                }
            }
        }
    }
    println!(
        "{strokes} potting strokes of open tables {from}-{to}, {n} draws per component and stroke"
    );
    println!(
        "| noise component | end from the end meant, median (mm) | 90th percentile (mm) | met a ball it did not meet as meant | potted |"
    );
    println!("|---|---|---|---|---|");
    for (k, (name, _)) in parts.iter().enumerate() {
        let median = percentile(&mut dist[k], 0.5);
        let p90 = percentile(&mut dist[k], 0.9);
        let d = draws[k].max(1) as f64;
        println!(
            "| {name} | {:.0} | {:.0} | {:.1} % | {:.1} % |",
            1e3 * median,
            1e3 * p90,
            100.0 * cannon[k] as f64 / d,
            100.0 * potted[k] as f64 / d
        );
    }
}
