use snooker_engine::cue::{self, Cue};
use snooker_engine::table::layout;
use snooker_engine::*;

fn main() {
    let dims = Default::default();
    let p = Params::default();
    for k in 0..24 {
        let mut balls = layout::break_off(&dims, p.ball_radius);
        let c = Cue {
            speed: 4.0 + 0.2 * k as f64,
            aim: 0.02 * (k as f64 - 12.0),
            offset: [0.004, -0.003],
            elevation: 0.1,
        };
        balls[0].state = cue::strike(&balls[0].state, &c, &p).unwrap().state;
        let setup = Setup {
            table: Table::snooker(&dims),
            params: p,
            models: Models::default(),
            balls,
        };
        let shot = simulate(&setup, &SimOptions::default()).unwrap();
        // find max overlap
        let mut worst = (0.0, 0.0, 0, 0);
        let n = (shot.duration / 5e-4) as usize;
        for s in 0..n {
            let t = s as f64 * 5e-4;
            let st: Vec<_> = shot.tracks.iter().map(|tr| tr.state_at(t, &p)).collect();
            for i in 0..st.len() {
                for j in i + 1..st.len() {
                    if st[i].motion == Motion::Pocketed || st[j].motion == Motion::Pocketed {
                        continue;
                    }
                    let ov = 2.0 * p.ball_radius - (st[i].pos - st[j].pos).norm();
                    if ov > worst.0 {
                        worst = (ov, t, i, j);
                    }
                }
            }
        }
        println!(
            "k={k} events={} dur={:.3} worst overlap {:.3e} at t={:.4} {} {}",
            shot.events.len(),
            shot.duration,
            worst.0,
            worst.1,
            shot.tracks[worst.2].id,
            shot.tracks[worst.3].id
        );
        if worst.0 > 1e-6 {
            let (i, j) = (worst.2, worst.3);
            for e in &shot.events {
                if e.balls.contains(&i) || e.balls.contains(&j) {
                    if e.t > 2.2 && e.t < 2.40 {
                        let names: Vec<_> =
                            e.balls.iter().map(|&b| shot.tracks[b].id.clone()).collect();
                        println!(
                            "  t={:.6} {} {:?} after={:?}",
                            e.t,
                            e.kind.name(),
                            names,
                            e.after
                                .iter()
                                .map(|s| (s.motion, s.vel.xy().norm()))
                                .collect::<Vec<_>>()
                        );
                    }
                }
            }
            for dt in [-0.2, -0.15, -0.1, -0.07, -0.06, -0.055, -0.05] {
                let t = worst.1 + dt;
                let a = shot.tracks[i].state_at(t, &p);
                let b = shot.tracks[j].state_at(t, &p);
                println!(
                    "  t={t:.4} gap={:.3e} {:?} {:?} va={:?} vb={:?}",
                    (a.pos - b.pos).norm() - 2.0 * p.ball_radius,
                    a.motion,
                    b.motion,
                    a.vel.xy(),
                    b.vel.xy()
                );
            }
            break;
        }
    }
}
