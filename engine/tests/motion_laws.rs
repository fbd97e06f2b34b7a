//! Every motion law through the whole engine, against its closed form (thesis §2.4.2, §5.1,
//! §5.3, §7.1.1): stun to roll, a strike at 7R/5, the rolling stop distance, sidespin decay,
//! the massé curve and free flight.

mod common;

use snooker_engine::cue::{self, Cue};
use snooker_engine::motion::Transition;
use snooker_engine::{BallState, EventKind, Motion, Params, SimOptions, Vec3, simulate};

fn one_ball(state: BallState, p: Params) -> snooker_engine::Shot {
    simulate(&common::one_ball_setup(state, p), &SimOptions::default()).unwrap()
}

fn moving(vel: Vec3, spin: Vec3, p: &Params) -> BallState {
    BallState {
        pos: Vec3::new(0.0, 0.0, p.ball_radius),
        vel,
        spin,
        motion: Motion::Sliding,
    }
}

#[test]
fn stun_rolls_at_five_sevenths_after_two_v_over_seven_mu_g() {
    let p = Params::default();
    for v0 in [0.5, 2.0, 6.0] {
        let shot = one_ball(moving(Vec3::new(v0, 0.0, 0.0), Vec3::zeros(), &p), p);
        let e = &shot.events[0];
        assert_eq!(e.kind, EventKind::Transition(Transition::SlideToRoll));
        let t = 2.0 * v0 / (7.0 * p.mu_slide * p.g);
        assert!((e.t - t).abs() < 1e-12 * t.max(1.0));
        assert!((e.after[0].vel.x - 5.0 / 7.0 * v0).abs() < 1e-12);
        // Distance while sliding: v0 t - mu g t^2 / 2.
        let x = v0 * t - 0.5 * p.mu_slide * p.g * t * t;
        assert!((e.after[0].pos.x - x).abs() < 1e-12);
    }
}

#[test]
fn a_strike_at_seven_fifths_r_rolls_at_once_and_stops_after_v2_over_2_mu_r_g() {
    let p = Params::default();
    // Contact at height 7R/5: a level cue's axis at 0.4 (R + r) above the centre (see cue.rs).
    let cue = Cue {
        speed: 1.2,
        aim: 0.4,
        offset: [0.0, 0.4 * (p.ball_radius + p.cue_tip_radius)],
        elevation: 0.0,
    };
    let start = BallState::at_rest(0.0, 0.0, p.ball_radius);
    let s = cue::strike(&start, &cue, &p).unwrap();
    assert_eq!(s.state.motion, Motion::Rolling);
    let shot = one_ball(s.state, p);
    assert_eq!(shot.events.len(), 1, "{:?}", shot.events);
    let e = &shot.events[0];
    assert_eq!(e.kind, EventKind::Transition(Transition::RollToStop));
    let v = s.state.vel.norm();
    let dist = (e.after[0].pos - start.pos).norm();
    let expect = v * v / (2.0 * p.mu_roll * p.g);
    assert!((dist - expect).abs() < 1e-12, "{dist} vs {expect}");
    assert!((e.t - v / (p.mu_roll * p.g)).abs() < 1e-12);
    // Heading kept: rolling is straight.
    let dir = e.after[0].pos - start.pos;
    assert!((dir.y.atan2(dir.x) - 0.4).abs() < 1e-12);
}

#[test]
fn sidespin_decays_linearly_at_22_rad_s2() {
    let p = Params::default();
    let mut s = BallState::at_rest(0.0, 0.0, p.ball_radius);
    s.spin.z = -33.0;
    let shot = one_ball(s, p);
    assert_eq!(shot.events.len(), 1);
    assert_eq!(
        shot.events[0].kind,
        EventKind::Transition(Transition::SpinToStop)
    );
    assert!((shot.events[0].t - 1.5).abs() < 1e-14);
    let mid = shot.tracks[0].state_at(0.5, &p);
    assert!((mid.spin.z - (-33.0 + 22.0 * 0.5)).abs() < 1e-12);
    // Sidespin on a rolling ball decays on its own clock while the ball rolls straight.
    let v = Vec3::new(1.0, 0.0, 0.0);
    let mut r = moving(v, Vec3::z().cross(&v) / p.ball_radius, &p);
    r.spin.z = 5.0;
    let shot = one_ball(r, p);
    let at = shot.tracks[0].state_at(0.1, &p);
    assert!((at.spin.z - (5.0 - 2.2)).abs() < 1e-12);
    assert!(
        at.pos.y.abs() < 1e-15,
        "sidespin must not bend a rolling ball"
    );
    assert_eq!(
        shot.events.len(),
        1,
        "sidespin ends inside the rolling phase"
    );
}

#[test]
fn overspin_and_backspin_reach_the_rolling_speed_whatever_mu_s() {
    // v_roll = 5/7 v0 + 2/7 R (w0 x e_z) (Alciatore; peers.md) for any mu_s.
    for mu in [0.1, 0.21, 0.4] {
        let p = Params {
            mu_slide: mu,
            ..Params::default()
        };
        for w in [-120.0, 0.0, 90.0] {
            let v0 = Vec3::new(1.5, 0.3, 0.0);
            let w0 = Vec3::new(-10.0, w, 0.0);
            let shot = one_ball(moving(v0, w0, &p), p);
            let e = shot
                .events
                .iter()
                .find(|e| e.kind == EventKind::Transition(Transition::SlideToRoll))
                .unwrap();
            let expect = 5.0 / 7.0 * v0 + 2.0 / 7.0 * p.ball_radius * w0.cross(&Vec3::z());
            assert!((e.after[0].vel - expect).norm() < 1e-12);
        }
    }
}

#[test]
fn a_steep_cue_with_side_curves_the_path_until_it_rolls() {
    // Massé (thesis §2.4.1.2, §6.1.5): a parabola while sliding, a straight line after.
    let p = Params::default();
    let cue = Cue {
        speed: 2.0,
        aim: 0.0,
        offset: [0.01, 0.0],
        elevation: 1.2,
    };
    let s = cue::strike(&BallState::at_rest(0.0, 0.0, p.ball_radius), &cue, &p).unwrap();
    let shot = one_ball(s.state, p);
    let roll = shot.events[0].t;
    let tr = &shot.tracks[0];
    let heading = |t: f64| {
        let v = tr.state_at(t, &p).vel;
        v.y.atan2(v.x)
    };
    assert!(
        (heading(0.0) - heading(roll)).abs() > 0.05,
        "no curve while sliding"
    );
    assert!(
        (heading(roll + 1e-3) - heading(roll + 0.2)).abs() < 1e-12,
        "rolling must be straight"
    );
    // The centre's path while sliding is a parabola: its second difference is constant.
    let pos = |t: f64| tr.state_at(t, &p).pos;
    let h = roll / 8.0;
    let d1 = pos(2.0 * h) - 2.0 * pos(h) + pos(0.0);
    let d2 = pos(6.0 * h) - 2.0 * pos(5.0 * h) + pos(4.0 * h);
    assert!((d1 - d2).norm() < 1e-12);
}

#[test]
fn free_flight_lands_after_two_vz_over_g_with_spin_frozen() {
    let p = Params::default();
    let s = BallState {
        pos: Vec3::new(0.0, 0.0, p.ball_radius),
        vel: Vec3::new(1.0, 0.0, 0.15),
        spin: Vec3::new(0.0, 20.0, 4.0),
        motion: Motion::Airborne,
    };
    let shot = one_ball(s, p);
    let land = &shot.events[0];
    assert_eq!(land.kind, EventKind::Transition(Transition::Landing));
    assert!((land.t - 0.3 / p.g).abs() < 1e-15);
    assert_eq!(land.after[0].spin, s.spin);
    assert!((land.after[0].pos.x - 0.3 / p.g).abs() < 1e-15);
    let top = shot.tracks[0].state_at(0.15 / p.g, &p);
    assert!((top.pos.z - p.ball_radius - 0.15 * 0.15 / (2.0 * p.g)).abs() < 1e-15);
}

#[test]
fn a_hop_opens_with_a_lift_off_at_its_impact_and_closes_with_a_landing() {
    // A rolling cue ball head-on into a resting ball hops off it (thesis §6.1.6: the contact's
    // friction pulls it up), a fraction of a millimetre.
    let p = Params::default();
    let r = p.ball_radius;
    let mut setup = common::one_ball_setup(
        BallState {
            pos: Vec3::new(0.0, 0.0, r),
            vel: Vec3::new(2.0, 0.0, 0.0),
            spin: Vec3::new(0.0, 2.0 / r, 0.0),
            motion: Motion::Rolling,
        },
        p,
    );
    setup.balls.push(snooker_engine::Ball {
        id: "red".into(),
        kind: snooker_engine::BallKind::Red,
        state: BallState::at_rest(0.3, 0.0, r),
    });
    let shot = simulate(&setup, &SimOptions::default()).unwrap();
    common::check_shot(&setup, &shot);
    let k = shot
        .events
        .iter()
        .position(|e| e.kind == EventKind::BallBall)
        .unwrap();
    let (hit, lift) = (&shot.events[k], &shot.events[k + 1]);
    assert_eq!(hit.after[0].motion, Motion::Airborne, "no hop: {hit:?}");
    assert_eq!(lift.kind, EventKind::LiftOff);
    assert_eq!((lift.t, &lift.balls), (hit.t, &vec![0]));
    assert_eq!(
        (lift.before[0], lift.after[0]),
        (hit.after[0], hit.after[0])
    );
    assert_eq!(EventKind::from_name("lift_off"), Some(EventKind::LiftOff));
    let landing = shot.events[k + 2..]
        .iter()
        .find(|e| e.balls.contains(&0))
        .unwrap();
    assert_eq!(landing.kind, EventKind::Transition(Transition::Landing));
    // One lift-off, the cue ball's: the red stays on the cloth.
    let lifts = shot.events.iter().filter(|e| e.kind == EventKind::LiftOff);
    assert_eq!(lifts.count(), 1);
    // Listed, not resolved: the cap on events counts the impacts and transitions only.
    assert_eq!(shot.stats.lift_offs, 1);
    assert_eq!(shot.stats.events + 1, shot.events.len());
    assert_eq!(shot.resolved_events(), shot.stats.events);
    let cap = |n| SimOptions {
        max_events: n,
        ..SimOptions::default()
    };
    assert_eq!(simulate(&setup, &cap(shot.stats.events)).unwrap(), shot);
    assert!(simulate(&setup, &cap(shot.stats.events - 1)).is_err());
    // The audit sees a lift-off missing, and one too many.
    let mut missing = shot.clone();
    missing.events.remove(k + 1);
    assert_eq!(snooker_engine::audit::flights(&missing).len(), 1);
    let mut extra = shot.clone();
    extra.events.insert(k + 2, lift.clone());
    assert_eq!(snooker_engine::audit::flights(&extra).len(), 1);
}
