//! Measures the pockets' windows on the engine: an object ball rolling at speed v towards a
//! pocket's mouth at angle alpha to the pocket's axis, from 0.6 m, offset sideways by s (mm);
//! prints for each (pocket kind, alpha, v) the potting offsets' extent (the half-width of the
//! window about the mouth's middle, and its centre).
use snooker_engine::{
    Ball, BallKind, BallState, EventKind, Models, Params, Setup, SimOptions, SnookerDims, Table,
    Vec3, simulate,
};

fn main() {
    let p = Params::default();
    let r = p.ball_radius;
    let table = Table::snooker(&SnookerDims::default());
    for name in ["top-left", "middle-left"] {
        let pocket = table.pockets.iter().find(|k| k.name == name).unwrap();
        let axis = (pocket.centre - pocket.mouth).normalize();
        for alpha_deg in [0.0f64, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0] {
            for &v in &[0.6, 1.5, 3.0] {
                let mut potted = Vec::new();
                for k in -100..=100 {
                    let s = k as f64 * 0.0005;
                    for sign in [1.0, -1.0] {
                        let a = sign * alpha_deg.to_radians();
                        // Direction of travel: the axis turned by a.
                        let dir = Vec3::new(
                            axis.x * a.cos() - axis.y * a.sin(),
                            axis.x * a.sin() + axis.y * a.cos(),
                            0.0,
                        );
                        let side = Vec3::new(-dir.y, dir.x, 0.0);
                        let start = pocket.mouth - 0.6 * dir + s * side;
                        if table
                            .placement_error(Vec3::new(start.x, start.y, r), r)
                            .is_some()
                        {
                            continue;
                        }
                        let mut st = BallState::at_rest(start.x, start.y, r);
                        st.vel = v * dir;
                        // Rolling: spin = z x v / R.
                        st.spin = Vec3::new(-st.vel.y / r, st.vel.x / r, 0.0);
                        st.motion = snooker_engine::Motion::Rolling;
                        let setup = Setup {
                            table: table.clone(),
                            params: p,
                            models: Models::default(),
                            balls: vec![Ball {
                                id: "red".into(),
                                kind: BallKind::Red,
                                state: st,
                            }],
                        };
                        let Ok(shot) = simulate(&setup, &SimOptions::default()) else {
                            continue;
                        };
                        let pot = shot.events.iter().any(|e| {
                            e.kind == EventKind::BallPocket && e.feature.as_deref() == Some(name)
                        });
                        if pot {
                            potted.push(sign * s);
                        }
                    }
                }
                // Half-widths each side (offsets to the pocket's left and right are mirror images
                // through the sign of alpha: report the narrower).
                let lo = potted.iter().cloned().fold(f64::INFINITY, f64::min);
                let hi = potted.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
                println!(
                    "{name:<12} alpha {alpha_deg:>2} v {v:.1}: potted {} offsets, from {:.1} to {:.1} mm",
                    potted.len(),
                    lo * 1e3,
                    hi * 1e3
                );
            }
        }
    }
}
