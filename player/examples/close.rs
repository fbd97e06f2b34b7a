//! The pot probability of the best plain stroke (a few speeds and heights, aimed by the
//! planner) when the cue ball lies close to the object ball, against the closed form.
use snooker_engine::{
    Ball, BallKind, BallState, Models, Params, Setup, SimOptions, SnookerDims, Table, Vec3,
};
use snooker_planner::{Noise, Problem, Request, ShotKind, Stroke, rng_for};
use snooker_player::chance::{self, Direct};

fn main() {
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
    let sd = chance::direction_sd(&noise, &p);
    let red = Vec3::new(3.1, 1.4, 0.0);
    let u = (pocket.mouth - red).normalize();
    let u = Vec3::new(u.x, u.y, 0.0);
    for &d in &[0.07, 0.3] {
        for &cut in &[55.0f64, 62.0, 68.0, 72.0, 76.0, 79.0] {
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
            let Ok(pr) = Problem::for_setup(setup, SimOptions::default(), req) else {
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
                    let mut pots = 0;
                    for k in 0..64 {
                        let ex = noise.apply(
                            &t.cue,
                            &pr.setup.balls[0].state,
                            &p,
                            &mut rng_for(3, &[k]),
                        );
                        if pr.trial(&ex, &line).is_some_and(|x| x.pots()) {
                            pots += 1;
                        }
                    }
                    let q = pots as f64 / 64.0;
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
