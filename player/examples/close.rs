//! The pot probability of the best plain stroke (a few speeds and heights, aimed by the
//! planner) when the cue ball lies close to the object ball, against the closed form.
mod common;

use snooker_engine::{Params, Vec3};
use snooker_planner::{Noise, ShotKind, Stroke};
use snooker_player::chance::{self, Direct};

fn main() {
    let p = Params::default();
    let r = p.ball_radius;
    let (table, mouth) = common::table();
    let pocket = table
        .pockets
        .iter()
        .find(|k| k.mouth == mouth)
        .unwrap()
        .clone();
    let noise = Noise::STANDARD;
    let sd = chance::direction_sd(&noise, &p);
    let red = Vec3::new(3.1, 1.4, 0.0);
    for &d in &[0.07, 0.3] {
        for &cut in &[55.0f64, 62.0, 68.0, 72.0, 76.0, 79.0] {
            let cue = common::cue_at(red, mouth, cut, d, r);
            let Some(pr) = common::problem(&table, &p, cue, red) else {
                println!("bad");
                continue;
            };
            let line = pr.lines().into_iter().find(|l| l.kind == ShotKind::Direct);
            let Some(line) = line else {
                println!("d {d} cut {cut}: no line");
                continue;
            };
            let mut best = (0.0, 0.0, 0.0);
            for &speed in &[0.35, 0.7, 1.4, 2.6] {
                for &h in &[-0.008, 0.0, 0.008] {
                    let s = Stroke {
                        speed,
                        side: 0.0,
                        height: h,
                        elevation: 0.035,
                        mouth: 0.0,
                    };
                    let Some(t) = pr.aimed(&s, &line) else {
                        continue;
                    };
                    if !t.pots() {
                        continue;
                    }
                    let q = common::pot_share(&pr, &line, &t.cue, &noise, 64);
                    if q > best.0 {
                        best = (q, speed, h);
                    }
                }
            }
            let est = Direct::new(cue, red, &pocket, r).map_or(0.0, |x| x.chance(&pocket, sd, r));
            println!(
                "d {d:.3} cut {cut:>2}: best {:.2} (speed {} h {}), closed form {est:.2}",
                best.0, best.1, best.2
            );
        }
    }
}
