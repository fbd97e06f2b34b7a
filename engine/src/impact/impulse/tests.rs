//! The solver's faster ways against the ways round them, and the pieces' own properties.

use super::events::{Event, K};
use super::mode::{CLOTH, Friction, Mode, PRIMARY};
use super::pair::{FIXED_DIM, Fixed, Free, N, Pair};
use super::phase::PhaseLaws;
use super::solve::{Paths, Recorder};
use super::*;
use crate::ball::Vec3;
use crate::impact::dopri::{ErrorMeasure, Events};
use crate::impact::sweep::Rng;

const R: f64 = 0.02625;
const MASS: f64 = 0.141;

/// A ball-ball or ball-cushion contact (as the Mathavan models set them up) and random
/// velocities that approach, with frictions up to 0.6.
fn random_impact(rng: &mut Rng, cushion: bool) -> (Impact, Kinematics) {
    let (mu, mu_cloth, e) = (
        rng.uniform(0.0, 0.6),
        rng.uniform(0.0, 0.6),
        rng.uniform(0.5, 1.0),
    );
    let angle = rng.uniform(0.0, std::f64::consts::TAU);
    let plan = Vec3::new(angle.cos(), angle.sin(), 0.0);
    // One ball in ten is in the air (off the cloth) at the impact.
    let lifted = rng.uniform(0.0, 1.0) < 0.1;
    let (bodies, normal, arm) = if cushion {
        let n = -(21f64.sqrt() / 5.0) * plan + 0.4 * Vec3::z();
        (
            [ImpactBody::ball(!lifted), ImpactBody::fixed()],
            n,
            [n, Vec3::zeros()],
        )
    } else {
        (
            [ImpactBody::ball(!lifted), ImpactBody::ball(true)],
            plan,
            [plan, -plan],
        )
    };
    let c = Impact {
        bodies,
        normal,
        arm,
        mu,
        mu_cloth,
        e,
        backing: None,
    };
    loop {
        let mut k = Kinematics {
            vel: [rng.vec(3.0), rng.vec(1.0)],
            spin: [rng.vec(3.0 / R), rng.vec(1.0 / R)],
        };
        for i in 0..2 {
            if c.bodies[i].on_cloth {
                k.vel[i].z = 0.0;
            }
            if c.bodies[i].is_fixed() {
                k.vel[i] = Vec3::zeros();
                k.spin[i] = Vec3::zeros();
            }
        }
        if c.scaled(&k, R).is_ok() {
            return (c, k);
        }
    }
}

/// A random mode: each contact off, slipping, starting or at zero, either stage.
fn random_mode(rng: &mut Rng) -> Mode {
    let mut mode = Mode::new(
        [Friction::Off; 3],
        rng.uniform(0.0, 1.0) < 0.5,
        rng.uniform(-1.0, 1.0),
        10f64.powf(rng.uniform(-9.0, 0.0)),
    );
    for law in &mut mode.friction {
        let r = rng.vec(1.0).normalize();
        *law = match (rng.uniform(0.0, 4.0)) as usize {
            0 => Friction::Off,
            1 => Friction::Slip(r),
            2 => Friction::Starting(r),
            _ => Friction::AtZero,
        };
    }
    mode
}

/// A random whole state of `c`, a fixed body's entries zero, balls on the cloth down (held)
/// or up (free).
fn random_state(rng: &mut Rng, c: &Impact) -> [f64; N] {
    let mut y = [0.0; N];
    for i in 0..2 {
        if !c.bodies[i].is_fixed() {
            let mut v = rng.vec(2.0);
            if c.bodies[i].on_cloth && rng.uniform(0.0, 1.0) < 0.5 {
                v.z = 0.0;
            }
            Free::put(&mut y, i, v, rng.vec(2.0));
        }
    }
    y[pair::WORK] = rng.uniform(-2.0, 2.0);
    y
}

/// The slopes, events and slips of `laws` at `y`, as bits.
fn laws_bits<const M: usize, P: Pair<M>, const Z: bool>(
    laws: &PhaseLaws<M, P, Z>,
    y: &[f64; M],
) -> (Vec<u64>, Vec<u64>, Vec<u64>) {
    let whole = P::whole(&laws.slopes(y));
    let events = laws.all(y);
    let slips = laws.contact.local::<M, P>(y).slip;
    (
        whole.iter().map(|v| v.to_bits()).collect(),
        events.iter().map(|v| v.to_bits()).collect(),
        slips
            .iter()
            .flat_map(|s| s.iter().map(|v| v.to_bits()))
            .collect(),
    )
}

#[test]
fn a_fixed_body_has_the_same_laws_on_the_reduced_state_as_on_the_whole() {
    // The laws written once, instantiated for a fixed body 1 (its velocities left out) and for
    // a free one of zero inverse mass: bitwise the same slopes, events and slips, with and
    // without contacts at zero slip.
    let mut rng = Rng(0x5eed_1234_abcd_0001);
    let mut compared = [0; 2];
    for _ in 0..10_000 {
        let (c, _) = random_impact(&mut rng, true);
        let y = random_state(&mut rng, &c);
        let z = Fixed::part(&y);
        let mode = random_mode(&mut rng);
        let (free, fixed) = if mode.any_at_zero() {
            (
                laws_bits(&PhaseLaws::<N, Free, true>::new(&c, &mode), &y),
                laws_bits(&PhaseLaws::<FIXED_DIM, Fixed, true>::new(&c, &mode), &z),
            )
        } else {
            (
                laws_bits(&PhaseLaws::<N, Free, false>::new(&c, &mode), &y),
                laws_bits(&PhaseLaws::<FIXED_DIM, Fixed, false>::new(&c, &mode), &z),
            )
        };
        assert_eq!(free, fixed, "{c:?} {y:?} {mode:?}");
        compared[usize::from(mode.any_at_zero())] += 1;
    }
    assert!(compared.iter().all(|&n| n > 1000), "{compared:?}");
}

/// Checks that each event function alone is bitwise its entry among all of them.
fn check_one_event<const M: usize, P: Pair<M>, const Z: bool>(
    laws: &PhaseLaws<M, P, Z>,
    y: &[f64; M],
) {
    let all = laws.all(y);
    for (e, value) in all.into_iter().enumerate() {
        assert_eq!(
            laws.one(y, e).to_bits(),
            value.to_bits(),
            "event {:?}",
            Event::at(e)
        );
    }
}

#[test]
fn each_event_function_alone_is_its_entry_among_all() {
    let mut rng = Rng(0x5eed_1234_abcd_0004);
    for case in 0..10_000 {
        let cushion = case % 2 == 1;
        let (c, _) = random_impact(&mut rng, cushion);
        let y = random_state(&mut rng, &c);
        let mode = random_mode(&mut rng);
        match (cushion, mode.any_at_zero()) {
            (false, false) => check_one_event(&PhaseLaws::<N, Free, false>::new(&c, &mode), &y),
            (false, true) => check_one_event(&PhaseLaws::<N, Free, true>::new(&c, &mode), &y),
            (true, false) => check_one_event(
                &PhaseLaws::<FIXED_DIM, Fixed, false>::new(&c, &mode),
                &Fixed::part(&y),
            ),
            (true, true) => check_one_event(
                &PhaseLaws::<FIXED_DIM, Fixed, true>::new(&c, &mode),
                &Fixed::part(&y),
            ),
        }
    }
}

#[test]
fn events_are_named_by_their_place() {
    for e in 0..K {
        assert_eq!(Event::at(e).index(), e);
    }
}

#[test]
fn the_reduced_state_gives_the_whole_states_integration_bitwise() {
    // A fixed cushion's velocities left out of the state change the cost of an impact, not
    // one bit of its result or its trace (Heun's step for a starting slip taken on either).
    let mut rng = Rng(0x5eed_1234_abcd_0002);
    let whole = Paths {
        reduce: false,
        establish: true,
    };
    for _ in 0..1_000 {
        let (c, k) = random_impact(&mut rng, true);
        let (mut t_reduced, mut t_whole) = (Vec::new(), Vec::new());
        let reduced = c.solve_with(&k, R, MASS, TOLERANCE, Some(&mut t_reduced), Paths::FAST);
        let general = c.solve_with(&k, R, MASS, TOLERANCE, Some(&mut t_whole), whole);
        assert_eq!(reduced, general, "{c:?} {k:?}");
        assert_eq!(t_reduced, t_whole, "{c:?} {k:?}");
    }
}

#[test]
fn heuns_step_establishes_a_slip_as_the_full_integration_does() {
    // Over random impacts, many with a slip growing out of zero (a rolling ball's cloth
    // contact): the same results to the solver's accuracy, and the shortcut is taken.
    let mut rng = Rng(0x5eed_1234_abcd_0003);
    let without = Paths {
        reduce: true,
        establish: false,
    };
    let (mut shortened, mut diffs) = (0, Vec::new());
    for case in 0..2_000 {
        let (c, mut k) = random_impact(&mut rng, case % 2 == 1);
        if case % 4 < 2 {
            // Rolling: the cloth slip under body 0 starts at zero.
            k.spin[0] = Vec3::z().cross(&k.vel[0]) / R;
        }
        let Ok(fast) = c.solve_with(&k, R, MASS, TOLERANCE, None, Paths::FAST) else {
            continue;
        };
        let slow = c.solve_with(&k, R, MASS, TOLERANCE, None, without).unwrap();
        // The shortcut changes the results at rounding level where it is taken.
        shortened += usize::from(fast.after != slow.after);
        let scale = (k.vel[0] - k.vel[1]).norm();
        let diff = (0..2)
            .map(|i| {
                let dv = (fast.after.vel[i] - slow.after.vel[i]).norm();
                let dw = (fast.after.spin[i] - slow.after.spin[i]).norm() * R;
                dv.max(dw) / scale
            })
            .fold(0.0, f64::max);
        diffs.push(diff);
    }
    // Where it was taken, the difference is of the order of the tolerance, and nowhere
    // near the solver's accuracy (1e-6 of V; these frictions reach 0.6).
    diffs.retain(|&d| d > 0.0);
    diffs.sort_by(f64::total_cmp);
    let n = diffs.len();
    assert!(n > 300 && shortened == n, "{shortened} impacts shortened");
    assert!(diffs[n / 2] < 1e-8, "median {:e}", diffs[n / 2]);
    assert!(diffs[n - 1] < 1e-6, "worst {:e}", diffs[n - 1]);
}

#[test]
fn a_compression_that_begins_parting_ends_at_once() {
    // A landing can turn a cushion's normal velocity from approaching by 1e-13 V to parting
    // with no event to see it (solve.rs): compression is over there, not pushed on for ever
    // (a fuzz scene's impulse "grew without bound" so).
    let mut rng = Rng(0x5eed_1234_abcd_0005);
    for case in 0..200 {
        let (c, k) = random_impact(&mut rng, case % 2 == 1);
        let (mut y, _) = c.scaled(&k, R).unwrap();
        // Approaching at 1 (scaled): body 0 less (1 + 1e-13) of the normal parts at 1e-13.
        let (v, w) = (
            Free::vel(&y, 0) - (1.0 + 1e-13) * c.normal,
            Free::spin(&y, 0),
        );
        Free::put(&mut y, 0, v, w);
        assert!(c.local::<N, Free>(&y).vn < 0.0);
        let mut recorder = Recorder {
            trace: None,
            contact: &c,
            v_scale: 1.0,
            mass: MASS,
        };
        let (_, out) = c
            .phases::<N, Free>(y, TOLERANCE, Paths::FAST, &mut recorder)
            .unwrap_or_else(|e| panic!("{e}: {c:?} {k:?}"));
        assert_eq!((out.impulse, out.compression_impulse), (0.0, 0.0));
    }
}

#[test]
fn slips_are_measured_relative_to_their_size() {
    // The same error in a slip: accepted on a large slip, rejected on one near zero,
    // where it would turn the friction's direction.
    let c = Impact {
        bodies: [ImpactBody::ball(true), ImpactBody::fixed()],
        normal: -Vec3::y(),
        arm: [-Vec3::y(), Vec3::zeros()],
        mu: 0.14,
        mu_cloth: 0.2,
        e: 0.98,
        backing: None,
    };
    let tol = 1e-9;
    let measure = c.measure(tol, |y: &[f64; N]| c.local::<N, Free>(y).slip);
    let mut err = [0.0; N];
    err[0] = 5.0 * tol; // along x: changes the nose's and the cloth's slip
    let mut large = [0.0; N];
    large[0] = 1.0;
    let mut small = [0.0; N];
    small[0] = 1e-8;
    assert!(measure.measure(&large, &large, &err) < 1.0);
    assert!(measure.measure(&small, &small, &err) > 1.0);
    // Unless it is dying out: its direction then steers friction only until it is gone.
    let mut shrinking = [0.0; N];
    shrinking[0] = 2e-8;
    assert!(measure.measure(&shrinking, &small, &err) < 1.0);
}

#[test]
fn errors_read_as_before() {
    // The typed errors keep the messages the simulator reports.
    let e = ImpactError::TooManyPhases { limit: 200 };
    assert_eq!(
        e.to_string(),
        "impact could not be resolved: more than 200 phases"
    );
    let e = ImpactError::NotApproaching { normal_speed: -1.5 };
    assert_eq!(
        e.reason(),
        "the bodies are not approaching (normal speed -1.5 m/s)"
    );
}

#[test]
fn held_frictions_keep_their_slips_at_zero_and_creeping_ones_grow_as_found() {
    // Coulomb's law at zero slip under the cloth's unilateral support (thesis §6.1.2): the
    // frictions the solve finds for contacts at zero slip, put into the laws themselves (the
    // cloth pressing on whichever balls those frictions push down), leave a holding contact's
    // slip rate at zero and, if it is the only contact at zero (the others' frictions then
    // stay as its creep was found with), grow a creeping one's as lambda times its direction.
    // The reaction is not affine across a ball's lift-off, so a solve that assumes the wrong
    // balls pressed gives frictions that do neither.
    let mut rng = Rng(0x5eed_1234_abcd_0005);
    let (mut held_checked, mut crept_checked, mut pressed_by_friction) = (0, 0, 0);
    for case in 0..20_000 {
        let (c, _) = random_impact(&mut rng, case % 2 == 1);
        let y = random_state(&mut rng, &c);
        let mut mode = random_mode(&mut rng);
        mode.friction[PRIMARY] = Friction::AtZero;
        for (i, k) in CLOTH.into_iter().enumerate() {
            mode.friction[k] = match (c.bodies[i].on_cloth, rng.uniform(0.0, 3.0) as usize) {
                (false, _) | (true, 0) => Friction::Off,
                (true, 1) => Friction::Slip(Impact::cloth_slip::<N, Free>(&y, i).normalize()),
                _ => Friction::AtZero,
            };
        }
        let loc = c.local::<N, Free>(&y);
        let (held, creeping) = c.at_zero::<N, Free>(&y, &loc, &mode);
        let f = c.forces_with::<N, Free>(&y, loc.slip[PRIMARY], &mode, &held);
        pressed_by_friction += usize::from(f.reaction.iter().any(|&r| r > 0.0));
        let rates = c
            .local::<N, Free>(&c.derivatives::<N, Free>(loc.vn, &f))
            .slip;
        let alone = mode
            .friction
            .iter()
            .filter(|&&law| law == Friction::AtZero)
            .count()
            == 1;
        for k in 0..3 {
            if mode.friction[k] != Friction::AtZero {
                continue;
            }
            let expected = match creeping[k] {
                None => {
                    held_checked += 1;
                    Vec3::zeros()
                }
                Some(_) if !alone => continue,
                Some(creep) => {
                    crept_checked += 1;
                    creep.rate * creep.dir
                }
            };
            assert!(
                (rates[k] - expected).norm() <= 1e-9,
                "contact {k}: slip rate {:?}, expected {expected:?}\n{c:?}\n{y:?}\n{mode:?}",
                rates[k]
            );
        }
    }
    assert!(
        held_checked > 10_000 && crept_checked > 1000 && pressed_by_friction > 5000,
        "{held_checked} held, {crept_checked} creeping, {pressed_by_friction} pressed"
    );
}

#[test]
fn a_slip_followed_quasi_statically_changes_along_its_steady_direction() {
    // A slip followed quasi-statically (Friction::QuasiStatic) meets friction mu N against its
    // steady direction, the one in which its rate is along it: put into the laws, that
    // friction changes the slip at lambda times that direction, growing (lambda > 0) or
    // shrinking (lambda < 0), wherever the solve finds one (its rate is NaN where it does not).
    let mut rng = Rng(0x5eed_1234_abcd_0006);
    let (mut growing, mut shrinking, mut none) = (0, 0, 0);
    for case in 0..20_000 {
        let (c, _) = random_impact(&mut rng, case % 2 == 1);
        let y = random_state(&mut rng, &c);
        let loc = c.local::<N, Free>(&y);
        let mut mode = Mode::new([Friction::Off; 3], true, 0.0, 1e-8);
        for k in 0..3 {
            let on_cloth = k == PRIMARY || c.bodies[k - 1].on_cloth;
            if on_cloth && c.coefficient(k) > 0.0 {
                mode.friction[k] = Friction::Slip(loc.slip[k].normalize());
            }
        }
        let k = if c.bodies[0].on_cloth && rng.uniform(0.0, 1.0) < 0.5 {
            CLOTH[0]
        } else {
            PRIMARY
        };
        mode.friction[k] = Friction::QuasiStatic(loc.slip[k].normalize(), 1.0);
        let (held, creeping) = c.at_zero::<N, Free>(&y, &loc, &mode);
        let creep = creeping[k].expect("a slip followed quasi-statically has a creep");
        if creep.rate.is_nan() {
            none += 1;
            continue;
        }
        let f = c.forces_with::<N, Free>(&y, loc.slip[PRIMARY], &mode, &held);
        let rates = c
            .local::<N, Free>(&c.derivatives::<N, Free>(loc.vn, &f))
            .slip;
        let expected = creep.rate * creep.dir;
        assert!(
            (rates[k] - expected).norm() <= 1e-9 * (1.0 + creep.drive),
            "contact {k}: slip rate {:?}, expected {expected:?}\n{c:?}\n{y:?}\n{mode:?}",
            rates[k]
        );
        if creep.rate > 0.0 {
            growing += 1;
        } else {
            shrinking += 1;
        }
    }
    assert!(
        growing > 2000 && shrinking > 2000,
        "{growing} growing, {shrinking} shrinking, {none} without a steady direction"
    );
}
