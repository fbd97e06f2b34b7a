//! One visit on an open table, printed stroke by stroke (a quick look, not a benchmark):
//! `cargo run --profile ci -p snooker-player --example visit -- SEED [EFFORT] [NOISE_SCALE]`.
use snooker_planner::Noise;
use snooker_player::{PlayOptions, Player, play};

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let seed: u64 = a.get(1).map_or(1, |s| s.parse().unwrap());
    let effort: u64 = a.get(2).map_or(1500, |s| s.parse().unwrap());
    let scale: f64 = a.get(3).map_or(1.0, |s| s.parse().unwrap());
    let frame = snooker_player::layouts::open_table_in_hand(seed);
    let opts = PlayOptions {
        noise: Noise::STANDARD.scaled(scale),
        seed,
        effort,
        ..PlayOptions::default()
    };
    let game = play(&frame, [&Player, &Player], &opts, |s| {
        let p = &s.decision.plan;
        println!(
            "{:>3} {:<7} {:<8} {:<13} {:<7} p={:.2} v={:+.2} pts={} foul={:?} t={:.2}s shots={}",
            s.number,
            p.kind.name(),
            p.ball,
            p.pocket,
            s.frame.state().on.name(),
            p.pot_probability,
            p.value,
            s.verdict.points,
            s.verdict.foul.as_ref().map(|f| f.reason),
            s.decision_time,
            s.decision.shots
        );
    })
    .unwrap();
    println!("break {} ({:?})", game.points(0), game.end);
}
