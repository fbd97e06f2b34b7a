//! The pot probability of a plain stroke (centre ball, aimed by the planner) at each cue speed
//! under the standard noise, for a red 0.9 m from a corner pocket at a few cuts and distances:
//! the speed's error is absolute (0.075 m/s), so a soft pot that barely reaches the pocket
//! fails (docs/playing.md, "Why the cue ball runs far: pace").
//!
//! `cargo run --release -p snooker-player --example speed_chance -- [SAMPLES]` (default 400).
mod common;

use snooker_engine::{Params, Vec3};
use snooker_planner::{Noise, ShotKind, Stroke};

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let n: u64 = a
        .get(1)
        .map_or(400, |s| s.parse().expect("SAMPLES: a count"));
    let p = Params::default();
    let r = p.ball_radius;
    let (table, mouth) = common::table();
    let noise = Noise::STANDARD;
    // 0.9 m out from the mouth along the pocket's diagonal.
    let red = Vec3::new(mouth.x - 0.9 * 0.707, mouth.y - 0.9 * 0.707, 0.0);
    for &(d, cut) in &[(0.25, 0.0f64), (0.25, 20.0), (0.25, 40.0), (0.6, 20.0)] {
        let cue = common::cue_at(red, mouth, cut, d, r);
        let pr = common::problem(&table, &p, cue, red).expect("two balls on the cloth");
        let line = pr
            .lines()
            .into_iter()
            .find(|l| l.kind == ShotKind::Direct)
            .expect("a direct line is open");
        let mut row = format!("d {d} cut {cut:>2}:");
        for &speed in &[0.35, 0.5, 0.7, 1.0, 1.4, 1.9, 2.6, 3.6] {
            let s = Stroke {
                speed,
                side: 0.0,
                height: 0.0,
                elevation: 0.035,
                mouth: 0.0,
            };
            let Some(t) = pr.aimed(&s, &line) else {
                row += " --";
                continue;
            };
            let q = common::pot_share(&pr, &line, &t.cue, &noise, n);
            row += &format!(" {speed}:{q:.3}");
        }
        println!("{row}");
    }
}
