//! The two impacts of `engine/benches/impacts.rs`, `n` times over, for instruction counts
//! (deterministic, unlike timings on a shared machine): `impact_count bb|cushion n` under
//! `valgrind --tool=callgrind`; the difference between n = 1000 and n = 0, over 1000, is the
//! count per impact.

use snooker_engine::impact::ball_ball::mathavan as bb;
use snooker_engine::impact::cushion::mathavan as cush;
use snooker_engine::impact::incoming;
use snooker_engine::{Params, Vec3};
use std::hint::black_box;

fn main() {
    let mut args = std::env::args().skip(1);
    let which = args.next().unwrap_or_default();
    let n: Option<usize> = args.next().map_or(Some(1), |s| s.parse().ok());
    let (Some(n), "bb" | "cushion") = (n, which.as_str()) else {
        eprintln!("usage: impact_count bb|cushion [N (default 1)]");
        std::process::exit(2);
    };
    let p = Params::default();
    let (cue, red) = incoming::typical_ball_ball(&p);
    let ball = incoming::typical_cushion(&p);
    for _ in 0..n {
        if which == "bb" {
            black_box(bb::resolve(black_box(&cue), black_box(&red), &p).unwrap());
        } else {
            black_box(cush::resolve(black_box(&ball), Vec3::y(), &p).unwrap());
        }
    }
    let o = bb::solve(&cue, &red, &p, None).unwrap();
    let c = cush::solve(&ball, Vec3::y(), &p, None).unwrap();
    eprintln!(
        "ball-ball: {} steps, {} phases; cushion: {} steps, {} phases",
        o.steps, o.phases, c.steps, c.phases
    );
}
