//! The jump shot and the bed's bounce (`e_bed`, motion/bed.rs; off by default, as the thesis's
//! cloth takes the vertical velocity: §6.1.6, §7.1.3): a cue inclined down drives the ball
//! into the bed, which gives back e_bed of the downward speed; a landing ball bounces, each
//! bounce e_bed times slower, until the rebound is under `bed::MIN_REBOUND`.

mod common;

use snooker_engine::cue::{self, Cue};
use snooker_engine::motion::{Transition, bed};
use snooker_engine::{Ball, BallKind, BallState, EventKind, Motion, Params, SimOptions, simulate};

fn at_rest(p: &Params) -> BallState {
    BallState::at_rest(0.0, 0.0, p.ball_radius)
}

fn centre(speed: f64, elevation_deg: f64) -> Cue {
    Cue {
        speed,
        aim: 0.0,
        offset: [0.0, 0.0],
        elevation: elevation_deg.to_radians(),
    }
}

fn bouncy(e_bed: f64) -> Params {
    Params {
        e_bed,
        ..Params::default()
    }
}

#[test]
fn the_thesis_bed_takes_the_cue_downward_impulse() {
    let p = Params::default();
    for e in [0.0, 10.0, 30.0, 60.0] {
        let s = cue::strike(&at_rest(&p), &centre(3.0, e), &p).unwrap();
        assert_eq!(s.state.vel.z, 0.0);
        assert_ne!(s.state.motion, Motion::Airborne);
    }
}

#[test]
fn a_steep_cue_makes_the_ball_jump_at_e_bed_of_its_downward_speed() {
    // A centre strike's impulse lies along the cue: the downward speed the bed stops is the
    // horizontal speed times tan(elevation), and the ball leaves upwards at e_bed of it, its
    // horizontal velocity and spin those of the thesis's strike to the bit.
    let (thesis, p) = (Params::default(), bouncy(0.5));
    for e in [5.0, 20.0, 35.0, 50.0] {
        for speed in [1.0, 4.0] {
            let flat = cue::strike(&at_rest(&thesis), &centre(speed, e), &thesis).unwrap();
            let jump = cue::strike(&at_rest(&p), &centre(speed, e), &p).unwrap();
            let down = flat.state.vel.xy().norm() * e.to_radians().tan();
            let want = bed::rebound(down, &p);
            assert!(
                (jump.state.vel.z - want).abs() <= 1e-12 * want.max(1.0),
                "{e} {speed}"
            );
            assert_eq!(jump.state.vel.xy(), flat.state.vel.xy());
            assert_eq!(jump.state.spin, flat.state.spin);
            let airborne = want > 0.0;
            assert_eq!(
                jump.state.motion == Motion::Airborne,
                airborne,
                "{e} {speed}"
            );
        }
    }
    // A level cue drives nothing into the bed.
    let level = cue::strike(&at_rest(&p), &centre(4.0, 0.0), &p).unwrap();
    assert_eq!(level.state.vel.z, 0.0);
}

#[test]
fn the_cloth_friction_acts_through_the_rebound_too() {
    // With the strike's cloth friction on, the bed's rebound impulse e_bed N carries friction
    // as well: at most mu (1 + e_bed) N in all, and the slip it leaves is smaller.
    let mut p = bouncy(0.5);
    p.mu_strike_cloth = 0.2;
    let mut dry = p;
    dry.e_bed = 0.0;
    let c = Cue {
        offset: [0.0, -0.01],
        ..centre(3.0, 40.0)
    };
    let (jump, flat) = (
        cue::strike(&at_rest(&p), &c, &p).unwrap(),
        cue::strike(&at_rest(&dry), &c, &dry).unwrap(),
    );
    let n = jump.state.vel.z * p.ball_mass / p.e_bed;
    let f = jump.cloth_friction.norm();
    assert!(f > flat.cloth_friction.norm());
    assert!(f <= p.mu_strike_cloth * (1.0 + p.e_bed) * n * (1.0 + 1e-12));
    let r = p.ball_radius;
    assert!(jump.state.slip(r).norm() < flat.state.slip(r).norm());
}

#[test]
fn bounces_die_out_each_e_bed_times_slower_and_each_opens_with_a_lift_off() {
    let p = bouncy(0.6);
    let s = cue::strike(&at_rest(&p), &centre(3.0, 40.0), &p)
        .unwrap()
        .state;
    let v0 = s.vel.z;
    assert!(v0 > 1.0, "{v0}");
    let setup = common::one_ball_setup(s, p);
    let shot = simulate(&setup, &SimOptions::default()).unwrap();
    common::check_shot(&setup, &shot);
    let landings: Vec<_> = shot
        .events
        .iter()
        .filter(|e| e.kind == EventKind::Transition(Transition::Landing))
        .collect();
    // Bounces while e^n v0 >= MIN_REBOUND, then a landing that stays down.
    let mut bounces = 0;
    while v0 * p.e_bed.powi(bounces + 1) >= bed::MIN_REBOUND {
        bounces += 1;
    }
    assert_eq!(landings.len() as i32, bounces + 1);
    let mut vz = v0;
    let mut t = 0.0;
    for (k, l) in landings.iter().enumerate() {
        // Each flight lasts 2 vz / g and comes down at vz.
        t += 2.0 * vz / p.g;
        assert!((l.t - t).abs() < 1e-12, "landing {k}: {} vs {t}", l.t);
        assert!((l.before[0].vel.z + vz).abs() < 1e-12);
        vz *= p.e_bed;
        let last = k == landings.len() - 1;
        assert_eq!(l.after[0].motion == Motion::Airborne, !last);
        if !last {
            assert!((l.after[0].vel.z - vz).abs() < 1e-12);
        }
    }
    // Each bounce is followed by its lift-off (the strike's own flight has none: it starts
    // the shot in the air, as a scene's vz > 0 does; formats.md).
    let lifts = shot.events.iter().filter(|e| e.kind == EventKind::LiftOff);
    assert_eq!(lifts.count() as i32, bounces);
    assert_eq!(shot.stats.lift_offs as i32, bounces);
    // The horizontal velocity is frozen in the air (thesis §6.1.6): the ball comes down on the
    // cloth at the strike's horizontal velocity.
    let down = landings.last().unwrap();
    assert_eq!(down.after[0].vel.xy(), s.vel.xy());
}

#[test]
fn a_jump_clears_a_ball_in_its_way() {
    // Peaking 2R above the cloth needs vz = sqrt(4 g R); a ball placed under the peak is
    // passed over without a contact, and the cue ball lands beyond it.
    let p = bouncy(0.6);
    let r = p.ball_radius;
    let s = cue::strike(&at_rest(&p), &centre(5.0, 45.0), &p)
        .unwrap()
        .state;
    let (vx, vz) = (s.vel.x, s.vel.z);
    assert!(vz * vz / (2.0 * p.g) > 2.2 * r, "too low a jump: {vz}");
    let under_peak = vx * vz / p.g;
    let mut setup = common::one_ball_setup(s, p);
    setup.balls.push(Ball {
        id: "red".into(),
        kind: BallKind::Red,
        state: BallState::at_rest(under_peak, 0.0, r),
    });
    let shot = simulate(&setup, &SimOptions::default()).unwrap();
    common::check_shot(&setup, &shot);
    assert!(
        shot.events.iter().all(|e| e.kind != EventKind::BallBall),
        "the jump met the red"
    );
    let first_landing = shot
        .events
        .iter()
        .find(|e| e.kind == EventKind::Transition(Transition::Landing))
        .unwrap();
    assert!(first_landing.after[0].pos.x > under_peak + 2.0 * r);
    assert_eq!(shot.final_states()[1], setup.balls[1].state);
}

#[test]
fn e_bed_is_validated() {
    let mut p = Params::default();
    assert!(p.validate().is_ok());
    for bad in [-0.1, 0.95, f64::NAN] {
        p.e_bed = bad;
        let err = p.validate().unwrap_err();
        assert!(err.to_string().contains("e_bed"), "{err}");
    }
}
