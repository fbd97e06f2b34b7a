//! How much the object ball's direction varies under the standard noise for a cue ball close
//! to it (the aim's lever is short there; what is left is throw and squirt varying).
use snooker_engine::{
    Ball, BallKind, BallState, Cue, EventKind, Models, Params, Setup, SimOptions, Table, simulate,
};
use snooker_planner::{Noise, rng_for};

fn main() {
    let p = Params::default();
    let r = p.ball_radius;
    let noise = Noise::STANDARD;
    for &d in &[0.06, 0.3, 1.0] {
        for &cut_deg in &[0.0f64, 20.0, 40.0, 60.0] {
            for &speed in &[0.4, 1.0, 2.5] {
                for &h in &[-0.008, 0.0, 0.008] {
                    let cut = cut_deg.to_radians();
                    let obj = BallState::at_rest(2.0, 0.9, r);
                    // The ghost ball at 2R from the object ball along -u, u the line at `cut` from +x.
                    let ghost = [2.0 - 2.0 * r * cut.cos(), 0.9 - 2.0 * r * cut.sin()];
                    let cue_pos = [ghost[0] - d, ghost[1]];
                    let cue = BallState::at_rest(cue_pos[0], cue_pos[1], r);
                    let aim = 0.0;
                    let mut dirs = Vec::new();
                    for k in 0..200u64 {
                        let mut rng = rng_for(1, &[k]);
                        let c = noise.apply(
                            &Cue {
                                speed,
                                aim,
                                offset: [0.0, h],
                                elevation: 0.035,
                            },
                            &cue,
                            &p,
                            &mut rng,
                        );
                        let mut b = Ball {
                            id: "cue".into(),
                            kind: BallKind::Cue,
                            state: cue,
                        };
                        if b.strike(&c, &p).is_err() {
                            continue;
                        }
                        let setup = Setup {
                            table: Table::open(),
                            params: p,
                            models: Models::default(),
                            balls: vec![
                                b,
                                Ball {
                                    id: "red".into(),
                                    kind: BallKind::Red,
                                    state: obj,
                                },
                            ],
                        };
                        let opts = SimOptions {
                            horizon: Some(3.0),
                            ..SimOptions::default()
                        };
                        let Ok(shot) = simulate(&setup, &opts) else {
                            continue;
                        };
                        let Some(e) = shot.events.iter().find(|e| e.kind == EventKind::BallBall)
                        else {
                            continue;
                        };
                        let v = e.after[1].vel;
                        dirs.push(v.y.atan2(v.x));
                    }
                    let n = dirs.len() as f64;
                    let m = dirs.iter().sum::<f64>() / n;
                    let sd = (dirs.iter().map(|x| (x - m).powi(2)).sum::<f64>() / n).sqrt();
                    let geo = d * noise.aim / (2.0 * r * cut.cos());
                    println!(
                        "d {d:.2} cut {cut_deg:>2} speed {speed:.1} h {h:+.3}: object sd {:.3} deg (aim lever alone {:.3} deg)",
                        sd.to_degrees(),
                        geo.to_degrees()
                    );
                }
            }
        }
    }
}
