//! The pot probability of a plain stroke (centre ball, aimed by the planner) at each cue speed
//! under the standard noise, for a red 0.9 m from a corner pocket at a few cuts and distances:
//! the speed's error is absolute (0.075 m/s), so a soft pot that barely reaches the pocket
//! fails (docs/playing.md, "Why the cue ball runs far: pace").
//!
//! `cargo run --release -p snooker-player --example speed_chance -- [SAMPLES]` (default 400).
use snooker_engine::{
    Ball, BallKind, BallState, Models, Params, Setup, SimOptions, SnookerDims, Table, Vec3,
};
use snooker_planner::{Noise, Problem, Request, ShotKind, Stroke, rng_for};

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let n: u64 = a.get(1).map_or(400, |s| s.parse().unwrap());
    let p = Params::default();
    let r = p.ball_radius;
    let table = Table::snooker(&SnookerDims::default());
    let pocket = table
        .pockets
        .iter()
        .find(|k| k.name == "top-left")
        .unwrap()
        .clone();
    let noise = Noise::STANDARD;
    let mouth = pocket.mouth;
    // 0.9 m out from the mouth along the pocket's diagonal.
    let red = Vec3::new(mouth.x - 0.9 * 0.707, mouth.y - 0.9 * 0.707, 0.0);
    let u = (mouth - red).normalize();
    let u = Vec3::new(u.x, u.y, 0.0);
    for &(d, cut) in &[(0.25, 0.0f64), (0.25, 20.0), (0.25, 40.0), (0.6, 20.0)] {
        let c = cut.to_radians();
        let ghost = red - 2.0 * r * u;
        let back = Vec3::new(
            u.x * c.cos() - u.y * c.sin(),
            u.x * c.sin() + u.y * c.cos(),
            0.0,
        );
        let cue = ghost - d * back;
        let balls = vec![
            Ball {
                id: "cue".into(),
                kind: BallKind::Cue,
                state: BallState::at_rest(cue.x, cue.y, r),
            },
            Ball {
                id: "red".into(),
                kind: BallKind::Red,
                state: BallState::at_rest(red.x, red.y, r),
            },
        ];
        let setup = Setup {
            table: table.clone(),
            params: p,
            models: Models::default(),
            balls,
        };
        let mut req = Request::new("red", "top-left", [cue.x, cue.y], &p);
        req.samples = 1;
        let pr = Problem::for_setup(setup, SimOptions::default(), req).unwrap();
        let line = pr
            .lines()
            .into_iter()
            .find(|l| l.kind == ShotKind::Direct)
            .unwrap();
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
            let mut pots = 0;
            for k in 0..n {
                let ex = noise.apply(&t.cue, &pr.setup.balls[0].state, &p, &mut rng_for(3, &[k]));
                if pr.trial(&ex, &line).is_some_and(|x| x.pots()) {
                    pots += 1;
                }
            }
            row += &format!(" {speed}:{:.3}", pots as f64 / n as f64);
        }
        println!("{row}");
    }
}
