//! Calibration of the closed-form pot chance against the engine: random positions of an open
//! table, every open direct pot of a red, struck stun at a medium pace (the heading solved by
//! the planner), sampled under the standard noise; prints the closed-form chance beside the
//! share potted, binned.
use snooker_engine::Vec3;
use snooker_planner::{Noise, Stroke, rng_for};
use snooker_player::candidates::{self, ELEVATION};
use snooker_player::chance::{self, Direct};

fn main() {
    let noise = Noise::STANDARD;
    let n = 48;
    let mut rows: Vec<(f64, f64, f64, f64)> = Vec::new();
    for seed in 1..=30u64 {
        let frame = snooker_rules::Frame::open_table(15, seed);
        let p = frame.params();
        let r = p.ball_radius;
        let sd = chance::direction_sd(&noise, p);
        let targets = candidates::targets(&frame);
        let cue = frame.cue_index().unwrap();
        let c = frame.balls()[cue].state.pos;
        for t in &targets {
            for line in t.problem.requested_lines() {
                if line.kind != snooker_planner::ShotKind::Direct {
                    continue;
                }
                let pocket = &frame.table().pockets[t.pocket];
                let b = frame.balls()[t.ball].state.pos;
                let Some(d) = Direct::new(
                    Vec3::new(c.x, c.y, 0.0),
                    Vec3::new(b.x, b.y, 0.0),
                    pocket,
                    r,
                ) else {
                    continue;
                };
                let est = d.chance(pocket, sd, r);
                let s = Stroke {
                    speed: 1.3,
                    side: 0.0,
                    height: 0.0,
                    elevation: ELEVATION,
                    mouth: 0.0,
                };
                let Some(trial) = t.problem.aimed(&s, &line) else {
                    continue;
                };
                if !trial.pots() {
                    continue;
                }
                let mut pots = 0;
                for k in 0..n {
                    let mut rng = rng_for(seed, &[t.ball as u64, t.pocket as u64, k]);
                    let ex = noise.apply(&trial.cue, &frame.balls()[cue].state, p, &mut rng);
                    if t.problem.trial(&ex, &line).is_some_and(|tr| tr.pots()) {
                        pots += 1;
                    }
                }
                rows.push((
                    est,
                    pots as f64 / n as f64,
                    d.approach.to_degrees(),
                    if pocket.name.starts_with("middle") {
                        1.0
                    } else {
                        0.0
                    },
                ));
            }
        }
    }
    for (lo, hi) in [
        (0.0, 0.2),
        (0.2, 0.4),
        (0.4, 0.6),
        (0.6, 0.8),
        (0.8, 0.95),
        (0.95, 1.01),
    ] {
        for mid in [0.0, 1.0] {
            let sel: Vec<_> = rows
                .iter()
                .filter(|r| r.0 >= lo && r.0 < hi && r.3 == mid)
                .collect();
            if sel.is_empty() {
                continue;
            }
            let m = sel.iter().map(|r| r.1).sum::<f64>() / sel.len() as f64;
            let e = sel.iter().map(|r| r.0).sum::<f64>() / sel.len() as f64;
            println!(
                "{} est [{lo:.2},{hi:.2}): n={:3} mean est {e:.2} measured {m:.2}",
                if mid == 1.0 { "middle" } else { "corner" },
                sel.len()
            );
        }
    }
    // By approach angle, for the easy ones (estimate > 0.8).
    for (lo, hi) in [
        (0.0, 15.0),
        (15.0, 30.0),
        (30.0, 45.0),
        (45.0, 60.0),
        (60.0, 90.0),
    ] {
        for mid in [0.0, 1.0] {
            let sel: Vec<_> = rows
                .iter()
                .filter(|r| r.2 >= lo && r.2 < hi && r.3 == mid)
                .collect();
            if sel.is_empty() {
                continue;
            }
            let m = sel.iter().map(|r| r.1).sum::<f64>() / sel.len() as f64;
            let e = sel.iter().map(|r| r.0).sum::<f64>() / sel.len() as f64;
            println!(
                "{} approach [{lo},{hi}): n={:3} mean est {e:.2} measured {m:.2}",
                if mid == 1.0 { "middle" } else { "corner" },
                sel.len()
            );
        }
    }
}
