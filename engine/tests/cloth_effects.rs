//! The cloth and bed effects beyond the thesis (engine/src/motion/cloth.rs) through the whole
//! engine: each against its own closed form or a fine independent integration of its
//! equations of motion, plus the event-detection sweep with all of them on.

mod common;

use proptest::prelude::*;
use snooker_engine::motion::Transition;
use snooker_engine::{
    Ball, BallKind, BallState, EventKind, Models, Motion, Params, Setup, Shot, SimOptions, Table,
    Vec3, simulate,
};

fn run(table: Table, p: Params, states: &[BallState]) -> Shot {
    let setup = Setup {
        table,
        params: p,
        models: Models::default(),
        balls: states
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let id = if i == 0 {
                    "cue".into()
                } else {
                    format!("red{i}")
                };
                Ball {
                    kind: BallKind::from_id(&id),
                    id,
                    state: *s,
                }
            })
            .collect(),
    };
    simulate(&setup, &SimOptions::default()).expect("simulation failed")
}

fn rolling(x: f64, y: f64, vel: Vec3, p: &Params) -> BallState {
    BallState {
        pos: Vec3::new(x, y, p.ball_radius),
        vel,
        spin: Vec3::z().cross(&vel) / p.ball_radius,
        motion: Motion::Rolling,
    }
}

/// Where a rolling ball stops under dv/dt = -mu_r g v^ + 5/7 (g slope + nap(v^)), by RK4 at
/// 10 microseconds, stopping when the speed would reach zero within a step.
fn reference_roll(p: &Params, v0: Vec3) -> Vec3 {
    let acc = |v: Vec3| {
        let d = v / v.norm();
        let body = Vec3::new(p.g * p.slope_x, p.g * p.slope_y, 0.0)
            + p.nap_drift * d.x * d.cross(&Vec3::z());
        -p.mu_roll * p.g * d + 5.0 / 7.0 * body
    };
    let h = 1e-5;
    let (mut x, mut v) = (Vec3::new(0.0, 0.0, p.ball_radius), v0);
    loop {
        let a = acc(v);
        if v.norm() <= -a.dot(&v) / v.norm() * h {
            // Last fraction of a step at the current deceleration.
            let t = v.norm() / (-a.dot(&v) / v.norm());
            return x + v * t / 2.0;
        }
        let k1 = (v, a);
        let k2 = (v + 0.5 * h * k1.1, acc(v + 0.5 * h * k1.1));
        let k3 = (v + 0.5 * h * k2.1, acc(v + 0.5 * h * k2.1));
        let k4 = (v + h * k3.1, acc(v + h * k3.1));
        x += h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
        v += h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
    }
}

fn final_pos(shot: &Shot, ball: usize) -> Vec3 {
    shot.tracks[ball].segments.last().unwrap().state.pos
}

#[test]
fn uphill_roll_stops_at_v2_over_2a_with_5_7_of_the_tilt() {
    // Straight up the slope: a = mu_r g + 5/7 g tilt (a sphere rolling on an incline).
    let tilt = 0.004;
    let p = Params {
        slope_x: -tilt,
        ..Params::default()
    };
    let v0 = 1.5;
    let shot = run(
        Table::open(),
        p,
        &[rolling(0.0, 0.0, Vec3::new(v0, 0.0, 0.0), &p)],
    );
    let a = p.mu_roll * p.g + 5.0 / 7.0 * p.g * tilt;
    let end = final_pos(&shot, 0);
    assert!((end.x - v0 * v0 / (2.0 * a)).abs() < 1e-9, "{end:?}");
    assert!(end.y.abs() < 1e-15);
    // Segments renew the law but are not events: one stop, many segments.
    assert_eq!(shot.events.len(), 1);
    assert_eq!(
        shot.events[0].kind,
        EventKind::Transition(Transition::RollToStop)
    );
    assert!(shot.stats.refreshes > 50);
    assert!(shot.tracks[0].segments.len() > 50);
}

#[test]
fn a_ball_rolling_across_a_slope_curves_downhill_as_integrated() {
    let p = Params {
        slope_y: -0.003,
        ..Params::default()
    };
    let v0 = Vec3::new(1.8, 0.0, 0.0);
    let shot = run(Table::open(), p, &[rolling(0.0, 0.0, v0, &p)]);
    let end = final_pos(&shot, 0);
    let want = reference_roll(&p, v0);
    // The drift is a metre over a 13 m roll on the endless cloth; the 10 ms segments with
    // their midpoint directions keep the end within 2 micrometres of the integration.
    assert!(want.y < -0.02, "{want:?}");
    assert!((end - want).norm() < 1e-5, "{end:?} vs {want:?}");
}

#[test]
fn nap_drifts_balls_along_the_table_to_the_right_and_not_across() {
    let p = Params {
        nap_drift: 0.01,
        ..Params::default()
    };
    for v0 in [Vec3::new(2.0, 0.0, 0.0), Vec3::new(-2.0, 0.0, 0.0)] {
        let shot = run(Table::open(), p, &[rolling(0.0, 0.0, v0, &p)]);
        let end = final_pos(&shot, 0);
        let want = reference_roll(&p, v0);
        assert!(want.y < -0.01, "{want:?}");
        assert!((end - want).norm() < 1e-5, "{end:?} vs {want:?}");
    }
    let across = run(
        Table::open(),
        p,
        &[rolling(0.0, 0.0, Vec3::new(0.0, 2.0, 0.0), &p)],
    );
    assert!(final_pos(&across, 0).x.abs() < 1e-12);
}

#[test]
fn speed_dependent_sliding_takes_the_integral_of_its_friction() {
    // A stun shot: the slip u = v shrinks at du/dt = -7/2 mu(u) g, so sliding lasts
    // t = int_0^u0 du / (7/2 g mu(u)) (Simpson, 20000 panels).
    let p = Params {
        mu_slide_low: 0.14,
        slide_speed_scale: 0.4,
        ..Params::default()
    };
    let v0 = 2.0;
    let state = BallState {
        pos: Vec3::new(0.0, 0.0, p.ball_radius),
        vel: Vec3::new(v0, 0.0, 0.0),
        spin: Vec3::zeros(),
        motion: Motion::Sliding,
    };
    let shot = run(Table::open(), p, &[state]);
    let e = &shot.events[0];
    assert_eq!(e.kind, EventKind::Transition(Transition::SlideToRoll));
    let f = |u: f64| {
        let mu = p.mu_slide - (p.mu_slide - p.mu_slide_low) * (-u / p.slide_speed_scale).exp();
        1.0 / (3.5 * p.g * mu)
    };
    let n = 20_000;
    let h = v0 / n as f64;
    let mut t = f(0.0) + f(v0);
    for k in 1..n {
        t += if k % 2 == 1 { 4.0 } else { 2.0 } * f(k as f64 * h);
    }
    t *= h / 3.0;
    let constant = 2.0 * v0 / (7.0 * p.mu_slide * p.g);
    assert!(
        t > constant * 1.02,
        "the low friction must show: {t} vs {constant}"
    );
    // The friction is taken at each 10 ms segment's mid-slip (the midpoint rule): second
    // order, 4e-5 of the time here, a few micrometres of travel.
    assert!((e.t - t).abs() < 1e-4 * t, "{} vs {t}", e.t);
    // Still rolls at 5/7 v0: friction through the contact keeps the angular momentum about it.
    assert!((e.after[0].vel.x - 5.0 / 7.0 * v0).abs() < 1e-9);
}

#[test]
fn cushion_restitution_falls_above_the_knee_only() {
    let base = Params::default();
    let soft = Params {
        e_cushion_falloff: 0.1,
        ..base
    };
    let rebound = |p: Params, v: f64| {
        let shot = run(
            Table::snooker(&Default::default()),
            p,
            &[rolling(1.0, 0.9, Vec3::new(0.0, v, 0.0), &p)],
        );
        let e = shot
            .events
            .iter()
            .find(|e| e.kind == EventKind::BallCushion)
            .unwrap();
        e.after[0].vel.y
    };
    // Below the knee the law is untouched, bit for bit.
    assert_eq!(rebound(base, 1.2), rebound(soft, 1.2));
    // Above it, e falls by falloff (v - knee): at 3 m/s from 0.98 to 0.83.
    let (hard, weak) = (rebound(base, 3.0), rebound(soft, 3.0));
    assert!(hard < weak && weak < 0.0, "{hard} {weak}");
    assert!(weak / hard < 0.95 && weak / hard > 0.8, "{}", weak / hard);
}

#[test]
fn nap_and_speed_dependent_friction_never_add_energy() {
    // The nap pushes across the motion and friction opposes the slip: no work is done on the
    // ball, so its kinetic energy falls between events.
    let p = Params {
        nap_drift: 0.02,
        mu_slide_low: 0.12,
        slide_speed_scale: 0.3,
        ..Params::default()
    };
    let state = BallState {
        pos: Vec3::new(0.0, 0.0, p.ball_radius),
        vel: Vec3::new(2.0, 0.7, 0.0),
        spin: Vec3::new(-30.0, 80.0, 25.0),
        motion: Motion::Sliding,
    };
    let shot = run(Table::open(), p, &[state]);
    let m = p.ball_mass;
    let inertia = 0.4 * m * p.ball_radius * p.ball_radius;
    let energy =
        |s: &BallState| 0.5 * m * s.vel.norm_squared() + 0.5 * inertia * s.spin.norm_squared();
    let track = &shot.tracks[0];
    let mut last = f64::INFINITY;
    for k in 0..4000 {
        let s = track.state_at(k as f64 * 1e-3, &p);
        let e = energy(&s);
        assert!(e <= last * (1.0 + 1e-12), "energy rose at {} ms", k);
        last = e;
    }
}

#[test]
fn a_tilt_that_would_roll_resting_balls_away_is_refused() {
    let p = Params {
        slope_x: 0.02,
        ..Params::default()
    };
    let setup = common::one_ball_setup(BallState::at_rest(0.0, 0.0, p.ball_radius), p);
    let err = simulate(&setup, &SimOptions::default()).unwrap_err();
    assert!(err.to_string().contains("slope_x"), "{err}");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 60, .. ProptestConfig::default() })]

    /// With every effect on at random strengths, detection still misses nothing.
    #[test]
    fn racks_on_a_real_cloth_never_overlap_or_escape(
        pts in prop::collection::vec((0.1f64..3.45, 0.1f64..1.68), 2..10),
        vel in (-4.0f64..4.0, -4.0f64..4.0),
        spin in (-150.0f64..150.0, -150.0f64..150.0, -60.0f64..60.0),
        slope in (-0.008f64..0.008, -0.008f64..0.008),
        nap in 0.0f64..0.03,
        low in 0.1f64..0.21,
        scale in 0.0f64..1.0,
        falloff in 0.0f64..0.2,
    ) {
        let p = Params {
            slope_x: slope.0,
            slope_y: slope.1,
            nap_drift: nap,
            mu_slide_low: low,
            slide_speed_scale: scale,
            e_cushion_falloff: falloff,
            ..Params::default()
        };
        let table = Table::snooker(&Default::default());
        let mut states: Vec<BallState> = Vec::new();
        for (x, y) in pts {
            let s = BallState::at_rest(x, y, p.ball_radius);
            if states.iter().all(|o| (o.pos - s.pos).norm() > 2.0 * p.ball_radius)
                && table.placement_error(s.pos, p.cushion_contact_distance()).is_none()
            {
                states.push(s);
            }
        }
        prop_assume!(states.len() >= 2);
        states[0].vel = Vec3::new(vel.0, vel.1, 0.0);
        states[0].spin = Vec3::new(spin.0, spin.1, spin.2);
        states[0].motion = Motion::Sliding;
        let setup = Setup {
            table,
            params: p,
            models: Models::default(),
            balls: Vec::new(),
        };
        let shot = run(setup.table.clone(), p, &states);
        let setup = Setup { balls: shot.tracks.iter().zip(&states).map(|(t, s)| Ball {
            id: t.id.clone(), kind: t.kind, state: *s }).collect(), ..setup };
        common::check_shot(&setup, &shot);
    }
}

#[test]
fn the_audits_sweep_takes_a_step_of_zero_as_its_finest() {
    // A zero dt asked for an endless list of sample times (a capacity overflow).
    let p = Params::default();
    let shot = run(
        Table::open(),
        p,
        &[rolling(0.0, 0.0, Vec3::new(0.5, 0.0, 0.0), &p)],
    );
    let setup = common::one_ball_setup(shot.tracks[0].segments[0].state, p);
    for dt in [0.0, -1.0, f64::NAN] {
        let s = snooker_engine::audit::sweep(&setup, &shot, dt);
        assert!(
            s.samples > 0 && s.samples <= 10_000_100,
            "{dt}: {}",
            s.samples
        );
    }
}
