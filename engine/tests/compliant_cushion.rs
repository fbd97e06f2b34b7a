//! The compliant cushion's limits (issue 25): below the rubber's travel it is the rigid
//! (thesis §6.2) cushion to the bit; it never gives energy to the ball; with the frictions off
//! it keeps the velocity along the cushion and the spin, and scales the normal velocity by the
//! restitution its energy law gives in closed form; harder impacts rebound slower relative
//! to their speed, as the thesis's measured rebounds do above about 2 m/s (§5.1.2).

use proptest::prelude::*;
use snooker_engine::impact::cushion::{compliant, mathavan};
use snooker_engine::impact::incoming::cushion as at_cushion;
use snooker_engine::{BallState, Params, Vec3};

/// Kinetic energy of a ball, J.
fn ke(s: &BallState, p: &Params) -> f64 {
    let i = 0.4 * p.ball_mass * p.ball_radius * p.ball_radius;
    0.5 * p.ball_mass * s.vel.norm_squared() + 0.5 * i * s.spin.norm_squared()
}

/// The plan normal of the cushion `at_cushion` builds, from the cushion to the ball.
const NORMAL: Vec3 = Vec3::new(0.0, 1.0, 0.0);

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Rolling or stunned balls up to 1.5 m/s (whose compression work stays below the
    /// rubber's full travel, M 1.853^2 / 2) rebound exactly as from the rigid cushion.
    #[test]
    fn below_its_travel_a_soft_cushion_is_the_rigid_one(
        v in 0.05f64..1.5,
        angle in 5f64..90.0,
        topspin in -1f64..1.0,
        sidespin in -1f64..1.0,
    ) {
        let p = Params::default();
        let ball = at_cushion(v, angle.to_radians(), topspin, sidespin * 0.5, &p);
        let rigid = mathavan::resolve(&ball, NORMAL, &p).unwrap();
        let soft = compliant::resolve(&ball, NORMAL, &p).unwrap();
        prop_assert_eq!(rigid, soft);
    }

    /// Whatever the speed, spin and backing, the ball leaves with no more energy than it
    /// brought (to the solver's tolerance), and with less than from the rigid cushion once
    /// the backing is met.
    #[test]
    fn energy_is_never_gained(
        v in 0.05f64..8.0,
        angle in 5f64..90.0,
        topspin in -1f64..1.0,
        sidespin in -1f64..1.0,
        bottom in 0.1f64..3.0,
        damping in 0.0f64..1.0,
        e in 0.5f64..1.0,
    ) {
        let p = Params {
            cushion_bottom_speed: bottom,
            cushion_backing_damping: damping,
            e_cushion: e,
            ..Params::default()
        };
        let ball = at_cushion(v, angle.to_radians(), topspin, sidespin * 0.5, &p);
        let soft = compliant::resolve(&ball, NORMAL, &p).unwrap();
        let before = ke(&ball, &p);
        prop_assert!(ke(&soft, &p) <= before * (1.0 + 1e-7), "{} > {}", ke(&soft, &p), before);
        prop_assert!(soft.vel.y > 0.0);
    }

    /// With no cushion or cloth friction the compliant cushion keeps the velocity along the
    /// cushion and the spin; the normal velocity leaves at e_eff of its approach, where the
    /// compression stores W = M v^2 / 2 (the cloth takes the nose's vertical push):
    /// e_eff^2 = (e^2 v_b^2 + (1 - alpha sqrt(v^2 - v_b^2))^2 (v^2 - v_b^2)) / v^2 above
    /// v_b, e below.
    #[test]
    fn frictionless_limit_is_the_energy_law_in_closed_form(
        v in 0.05f64..8.0,
        angle in 5f64..90.0,
        topspin in -1f64..1.0,
        sidespin in -1f64..1.0,
        bottom in 0.1f64..3.0,
        damping in 0.0f64..0.5,
    ) {
        let p = Params {
            mu_cushion: 0.0,
            mu_slide: 0.0,
            mu_slide_low: 0.0,
            cushion_bottom_speed: bottom,
            cushion_backing_damping: damping,
            ..Params::default()
        };
        let ball = at_cushion(v, angle.to_radians(), topspin, sidespin * 0.5, &p);
        let soft = compliant::resolve(&ball, NORMAL, &p).unwrap();
        let vn = -ball.vel.y;
        let e = p.e_cushion;
        let e_eff = if vn <= bottom {
            e
        } else {
            let over = vn * vn - bottom * bottom;
            let eb = (1.0 - damping * over.sqrt()).max(0.0);
            ((e * e * bottom * bottom + eb * eb * over) / (vn * vn)).sqrt()
        };
        prop_assert!((soft.vel.x - ball.vel.x).abs() <= 1e-9 * v);
        prop_assert!((soft.spin - ball.spin).norm() * p.ball_radius <= 1e-9 * v);
        prop_assert!((soft.vel.y - e_eff * vn).abs() <= 1e-7 * v,
            "{} vs {}", soft.vel.y, e_eff * vn);
    }
}

/// A rolling ball into the cushion square on: the rebound's share of the approach falls
/// once the backing is met, and the rebound speed still grows with the approach speed over
/// the game's range (thesis fig. 5.7: 0.28-3.5 m/s).
#[test]
fn hard_impacts_rebound_relatively_slower() {
    let p = Params::default();
    let rebound = |v: f64| {
        let ball = at_cushion(v, 90f64.to_radians(), 1.0, 0.0, &p);
        compliant::resolve(&ball, NORMAL, &p).unwrap().vel.y
    };
    let rigid = |v: f64| {
        let ball = at_cushion(v, 90f64.to_radians(), 1.0, 0.0, &p);
        mathavan::resolve(&ball, NORMAL, &p).unwrap().vel.y
    };
    let mut last = 0.0;
    for k in 1..=35 {
        let v = 0.1 * k as f64;
        let r = rebound(v);
        assert!(r > last, "rebound {r} at {v} m/s not above {last}");
        assert!(r <= rigid(v) + 1e-12);
        last = r;
    }
    assert!(rebound(3.5) / 3.5 < rebound(2.0) / 2.0);
    assert!(rebound(3.5) < 0.95 * rigid(3.5));
}

/// The compliant cushion's impacts are solved as accurately as the rigid one's: within 1e-6
/// of the converged solution (velocities and R w, as a fraction of V) over 20,000 random
/// impacts at 0.05-6 m/s, most of those above 1.853 m/s meeting the backing.
#[test]
fn twenty_thousand_random_compliant_impacts_are_within_one_in_a_million() {
    use snooker_engine::impact::impulse::TOLERANCE;
    use snooker_engine::impact::sweep;
    let p = Params::default();
    let mut rng = sweep::Rng(sweep::SEED);
    let mut worst: f64 = 0.0;
    for _ in 0..20_000 {
        let mut impact = sweep::random_impact(&mut rng, true);
        impact.contact.backing = Some(p.cushion_backing());
        let (err, _) = sweep::convergence(&impact, TOLERANCE);
        assert!(err < 1e-6, "{}: {err:e}", impact.text);
        worst = worst.max(err);
    }
    eprintln!("worst {worst:e}");
}
