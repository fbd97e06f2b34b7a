//! Two touching balls pressed together (issue 21's chatter): a resting contact is a train of
//! micro-collisions (`impact/separation.rs`), one event each, never a hop. Two reds touching, one
//! pressed into the other by its friction (red4 with overspin behind red10 with backspin),
//! met 461 times in 0.31 s and each impact launched a 0.1 mm/s hop: an airborne phase and a
//! landing for every touch.
//!
//! The bound: after a micro-collision the pair parts at `MIN_SEPARATION` at least, and no
//! law on the cloth accelerates a ball by more than a = mu g + g |tilt| + |nap| (mu the largest
//! of the cloth's frictions), so their gap closes again no sooner than
//! 2 MIN_SEPARATION / (2 a), less the time the gap takes to cross the contact detection's band
//! (`audit::least_remeet_gap`, about 2e-6 s): at most about a / MIN_SEPARATION impacts per pair
//! per second (2,060 on the thesis's cloth). `snooker_engine::audit` checks it on every shot
//! (`resting_contacts`); this test checks it explicitly too, and that the bound is reached.

use snooker_engine::impact::separation::RESTING_APPROACH;
use snooker_engine::impact::sweep::Rng;
use snooker_engine::{
    Ball, BallKind, BallState, EventKind, Models, Motion, Params, Setup, Shot, Table, Vec3,
};
use snooker_engine::{audit, simulate};

fn ball(id: &str, pos: Vec3, vel: Vec3, spin: Vec3) -> Ball {
    Ball {
        id: id.into(),
        kind: BallKind::Red,
        state: BallState {
            pos,
            vel,
            spin,
            motion: Motion::Stationary,
        },
    }
}

/// Checks the pair's impacts in `shot`: no micro-collision lifts a ball off the cloth, and
/// after one the pair meets again no sooner than the bound allows. Returns the number of
/// impacts and of micro-collisions.
fn check_pair(setup: &Setup, shot: &Shot) -> (usize, usize) {
    let p = &shot.params;
    let least_gap = audit::least_remeet_gap(p);
    let impacts: Vec<_> = shot
        .events
        .iter()
        .filter(|e| e.kind == EventKind::BallBall)
        .collect();
    let mut resting = 0;
    for (k, e) in impacts.iter().enumerate() {
        let approach = e.normal_speed.unwrap();
        if approach > RESTING_APPROACH {
            continue;
        }
        resting += 1;
        for (b, a) in e.before.iter().zip(&e.after) {
            if b.motion != Motion::Airborne {
                assert_ne!(
                    a.motion,
                    Motion::Airborne,
                    "a micro-collision lifted a ball: {e:?}"
                );
            }
        }
        let on_cloth = e.after.iter().all(|s| s.motion != Motion::Airborne);
        if let Some(next) = impacts.get(k + 1)
            && on_cloth
        {
            assert!(
                next.t - e.t >= least_gap * (1.0 - 1e-6),
                "met again after {:e} s (bound {least_gap:e} s)",
                next.t - e.t
            );
        }
    }
    let broken = audit::audit(setup, shot);
    assert!(broken.is_empty(), "{broken:?}");
    (impacts.len(), resting)
}

fn pair_setup(p: Params, a: Ball, b: Ball) -> Setup {
    Setup {
        table: Table::open(),
        params: p,
        models: Models::default(),
        balls: vec![a, b],
    }
}

#[test]
fn a_ball_pressed_into_another_chatters_without_hops() {
    // The class: red4 with overspin behind red10 with backspin, touching and moving
    // together at 0.5 m/s; each is pressed into the other by its cloth friction.
    let p = Params::default();
    let r = p.ball_radius;
    let setup = pair_setup(
        p,
        ball(
            "red4",
            Vec3::new(1.0, 0.9, r),
            Vec3::new(0.5, 0.0, 0.0),
            Vec3::new(0.0, 60.0, 0.0),
        ),
        ball(
            "red10",
            Vec3::new(1.0 + 2.0 * r, 0.9, r),
            Vec3::new(0.5, 0.0, 0.0),
            Vec3::new(0.0, -20.0, 0.0),
        ),
    );
    let shot = simulate(&setup, &Default::default()).unwrap();
    let (impacts, resting) = check_pair(&setup, &shot);
    // Pressed at the largest relative acceleration there is (each ball's whole sliding
    // friction), the train runs at its bound: 2,060 touches a second, for about 0.2 s.
    assert!(resting > 300 && impacts == resting, "{impacts} {resting}");
    let landings = shot
        .events
        .iter()
        .filter(|e| e.kind == EventKind::Transition(snooker_engine::motion::Transition::Landing))
        .count();
    assert_eq!(landings, 0);
    assert!(shot.events.len() < impacts + 20, "{}", shot.events.len());
}

#[test]
fn touching_pairs_with_small_relative_speeds_meet_within_the_bound() {
    let mut rng = Rng(0x21_c4a7);
    let (mut impacts, mut resting) = (0, 0);
    for k in 0..300 {
        let mut p = Params::default();
        if k % 2 == 1 {
            // Any frictions and restitutions, and gravity from the Moon's to Jupiter's.
            p.mu_slide = rng.uniform(0.05, 1.0);
            p.mu_slide_low = p.mu_slide;
            p.mu_ball = rng.uniform(0.0, 1.0);
            p.e_ball = rng.uniform(0.0, 1.0);
            p.g = rng.uniform(1.0, 25.0);
        }
        let r = p.ball_radius;
        let along = rng.uniform(0.0, std::f64::consts::TAU);
        let n = Vec3::new(along.cos(), along.sin(), 0.0);
        let common = rng.vec(2.0).component_mul(&Vec3::new(1.0, 1.0, 0.0));
        // Small relative speeds (up to 3 mm/s, either way along the line of centres and across
        // it), and spins that press the two together or pull them apart.
        let rel = rng.uniform(-3e-3, 3e-3) * n + rng.uniform(-3e-3, 3e-3) * n.cross(&Vec3::z());
        let spin = |rng: &mut Rng| rng.vec(60.0);
        let a = ball("red1", Vec3::new(1.0, 1.0, r), common, spin(&mut rng));
        let b = ball(
            "red2",
            Vec3::new(1.0, 1.0, r) + 2.0 * r * n,
            common + rel,
            spin(&mut rng),
        );
        let setup = pair_setup(p, a, b);
        let shot =
            simulate(&setup, &Default::default()).unwrap_or_else(|e| panic!("pair {k}: {e}"));
        let (i, s) = check_pair(&setup, &shot);
        impacts += i;
        resting += s;
    }
    println!("{impacts} impacts, {resting} of them micro-collisions");
    assert!(resting > 1000, "{resting}");
}
