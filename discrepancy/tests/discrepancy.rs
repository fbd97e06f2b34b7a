//! The discrepancy workflow on data with effects hidden in it (issue 6): for every catalogue
//! effect, data made with it and a model without it -> the workflow names it, recovers its
//! parameters within 10% and shrinks the RMS gap to at most 1.5x the camera noise; data with
//! nothing hidden -> nothing named; two effects -> both; an effect outside the catalogue ->
//! "unexplained" and no name.

use snooker_discrepancy::data::MeasuredStrike;
use snooker_discrepancy::synth::{Camera, Hidden, Uncatalogued, film};
use snooker_discrepancy::{Effect, Findings, Measurement, Model, Nuisance, Options, ShotData, run};
use snooker_engine::cue::Cue;
use snooker_engine::{Ball, BallKind, BallState, Models, Motion, Params, Setup, Table, Vec3};

const NOISE: f64 = 5e-4;

fn ball(id: &str, x: f64, y: f64) -> Ball {
    Ball {
        id: id.into(),
        kind: BallKind::from_id(id),
        state: BallState::at_rest(x, y, Params::default().ball_radius),
    }
}

fn moving(mut b: Ball, vel: [f64; 2], spin: [f64; 3]) -> Ball {
    b.state.vel = Vec3::new(vel[0], vel[1], 0.0);
    b.state.spin = Vec3::new(spin[0], spin[1], spin[2]);
    b.state.motion = Motion::Sliding;
    b
}

/// A shot on the full table.
fn shot(name: &str, balls: Vec<Ball>, nuisances: Vec<Nuisance>) -> ShotData {
    ShotData {
        name: name.into(),
        setup: Setup {
            table: Table::snooker(&Default::default()),
            params: Params::default(),
            models: Models::default(),
            balls,
        },
        strike: None,
        samples: Vec::new(),
        observables: Vec::new(),
        nuisances,
    }
}

/// The cue ball sent round the table: sliding, rolling, off three cushions, travelling along
/// and across the table.
fn round_the_table() -> ShotData {
    shot(
        "round-the-table",
        vec![moving(ball("cue", 0.8, 0.5), [1.9, 0.9], [0.0, 0.0, 0.0])],
        vec![Nuisance::Vel(0), Nuisance::Spin(0)],
    )
}

/// A screw shot: the cue ball with strong backspin, sliding long at high slip.
fn screw() -> ShotData {
    shot(
        "screw",
        vec![moving(
            ball("cue", 0.8, 0.9),
            [2.2, 0.25],
            [-8.0, -150.0, 0.0],
        )],
        vec![Nuisance::Vel(0), Nuisance::Spin(0)],
    )
}

/// A 30-degree cut of a red by a rolling cue ball; both tracked.
fn cut() -> ShotData {
    let r = Params::default().ball_radius;
    let (red_x, red_y) = (1.8, 0.9);
    let cut: f64 = 30f64.to_radians();
    let contact = Vec3::new(red_x, red_y, r) - 2.0 * r * Vec3::new(cut.cos(), cut.sin(), 0.0);
    let v = 1.6;
    let start_x = contact.x - 0.5;
    shot(
        "cut",
        vec![
            moving(ball("cue", start_x, contact.y), [v, 0.0], [0.0, v / r, 0.0]),
            ball("red", red_x, red_y),
        ],
        vec![Nuisance::Vel(0), Nuisance::Spin(0)],
    )
}

/// Fast cushion impacts with sidespin, at an angle.
fn cushions() -> ShotData {
    shot(
        "cushions",
        vec![moving(
            ball("cue", 1.2, 0.4),
            [2.2, 3.0],
            [20.0, -15.0, 70.0],
        )],
        vec![Nuisance::Vel(0), Nuisance::Spin(0)],
    )
}

/// A ball rolling square across the table at `v` m/s into the top cushion, and back and forth
/// between the long cushions: hard rebounds, then softer ones.
fn rebound(v: f64) -> ShotData {
    let r = Params::default().ball_radius;
    shot(
        &format!("rebound-{v}"),
        vec![moving(ball("cue", 1.0, 1.2), [0.0, v], [-v / r, 0.0, 0.0])],
        vec![Nuisance::Vel(0), Nuisance::Spin(0)],
    )
}

/// A strike with side: the ball leaves off the cue's axis by squirt.
fn side_strike() -> ShotData {
    let mut s = shot(
        "side-strike",
        vec![ball("cue", 0.7, 0.6)],
        vec![Nuisance::StrikeSpeed],
    );
    let cue = Cue {
        speed: 2.4,
        aim: 0.15,
        offset: [0.012, 0.004],
        elevation: 0.08,
    };
    s.strike = Some(MeasuredStrike {
        ball: 0,
        before: s.setup.balls[0].state,
        cue,
    });
    s
}

/// Films `shots` under `base` with `hidden` on, and returns the measurement the workflow
/// starts from: `base`, with the fitted quantities of the scene put 10% off their true values
/// (as a guess would be).
fn measure(shots: Vec<ShotData>, base: Model, hidden: &Hidden, seed: u64) -> Measurement {
    let truth = hidden.truth(&base);
    let camera = Camera {
        seed,
        ..Camera::default()
    };
    let shots = shots
        .into_iter()
        .map(|mut s| {
            let (_, samples) = film(&s, &truth, &hidden.uncatalogued, &camera).unwrap();
            s.samples = samples;
            for b in &mut s.setup.balls {
                b.state.spin *= 0.9;
            }
            if let Some(st) = &mut s.strike {
                st.cue.speed *= 0.9;
            }
            s
        })
        .collect();
    Measurement {
        shots,
        noise: NOISE,
        model: base,
    }
}

fn default_model() -> Model {
    Model {
        params: Params::default(),
        models: Models::default(),
    }
}

fn without(effects: &[Effect]) -> Model {
    effects
        .iter()
        .fold(default_model(), |m, e| e.switch_off(&m))
}

fn report(o: &Findings) -> String {
    let mut s = format!(
        "baseline gap {:.2} mm, chi2/dof {:.2}\n",
        o.baseline_state.gap.rms * 1e3,
        o.baseline_state.reduced_chi2
    );
    for st in &o.steps {
        s += &format!(
            "named {} dBIC {:.1} gap {:.3} mm: {:?}\n",
            st.effect.id(),
            st.delta_bic,
            st.gap.rms * 1e3,
            st.fitted
                .iter()
                .map(|f| (f.effect.id(), f.values.clone(), f.errors.clone()))
                .collect::<Vec<_>>()
        );
        for c in &st.candidates {
            s += &format!(
                "   {} dBIC {:.1} share {:.2} {}\n",
                c.effect.id(),
                c.delta_bic,
                c.share,
                c.verdict
            );
        }
    }
    for c in &o.last_candidates {
        s += &format!(
            "   last: {} dBIC {:.1} share {:.2} {}\n",
            c.effect.id(),
            c.delta_bic,
            c.share,
            c.verdict
        );
    }
    s += &format!(
        "final gap {:.3} mm chi2/dof {:.3} unexplained {} {:?}\n",
        o.final_state.gap.rms * 1e3,
        o.final_state.reduced_chi2,
        o.unexplained,
        o.unexplained_where
    );
    s
}

/// One catalogue effect hidden in data made for it, and the model the workflow starts from
/// (the thesis's, with the effect off).
struct Case {
    effect: Effect,
    values: Vec<f64>,
    shots: fn() -> Vec<ShotData>,
    base: Model,
}

/// The case of `effect`: data in which it shows, at a realistic size.
fn case(effect: Effect) -> Case {
    let (values, shots): (Vec<f64>, fn() -> Vec<ShotData>) = match effect {
        Effect::RollingResistance => (vec![0.0128], || vec![round_the_table()]),
        Effect::SpeedDependentSliding => (vec![0.14, 0.5], || vec![screw(), round_the_table()]),
        Effect::SidespinDecay => (vec![22.0], || vec![cushions()]),
        Effect::CushionSpeedRestitution => (vec![0.15], || vec![cushions()]),
        Effect::BallRestitution => (vec![0.89], || vec![cut()]),
        Effect::BallFriction => (vec![0.05], || vec![cut()]),
        Effect::CushionFriction => (vec![0.14], || vec![cushions()]),
        Effect::NapDrift => (vec![0.02], || vec![round_the_table()]),
        Effect::TableSlope => (vec![0.001, -0.0006], || vec![round_the_table()]),
        Effect::Squirt => (vec![0.0069], || vec![side_strike()]),
        Effect::CompliantCushion => (vec![1.853, 0.0692], || vec![rebound(2.5), rebound(3.5)]),
    };
    Case {
        effect,
        values,
        shots,
        base: without(&[effect]),
    }
}

/// Runs the workflow on `c`'s data made with noise seed `seed`; None when it names the effect,
/// recovers its parameters within 10%, leaves a gap of at most 1.5x the noise and nothing
/// unexplained, else what went wrong.
fn check(c: &Case, seed: u64) -> Option<String> {
    let hidden = Hidden {
        effects: vec![(c.effect, c.values.clone())],
        uncatalogued: Vec::new(),
    };
    let m = measure((c.shots)(), c.base, &hidden, seed);
    let o = run(&m, &Options::default()).unwrap();
    let text = report(&o);
    eprintln!("{} seed {seed}\n{text}", c.effect.id());
    if o.named() != vec![c.effect] {
        return Some(format!("named {:?}\n{text}", o.named()));
    }
    let fitted = &o.steps[0].fitted[0];
    for (got, want) in fitted.values.iter().zip(&c.values) {
        if (got - want).abs() > 0.1 * want.abs() {
            return Some(format!("fitted {got} for {want}\n{text}"));
        }
    }
    if o.final_state.gap.rms > 1.5 * NOISE || o.unexplained {
        return Some(format!("gap or unexplained residual left\n{text}"));
    }
    None
}

fn finds(effect: Effect) {
    if let Some(why) = check(&case(effect), 7) {
        panic!("{}: {why}", effect.id());
    }
}

#[test]
fn rolling_resistance_is_found() {
    finds(Effect::RollingResistance);
}

#[test]
fn speed_dependent_sliding_is_found() {
    finds(Effect::SpeedDependentSliding);
}

#[test]
fn sidespin_decay_is_found() {
    finds(Effect::SidespinDecay);
}

#[test]
fn cushion_speed_restitution_is_found() {
    finds(Effect::CushionSpeedRestitution);
}

#[test]
fn ball_restitution_is_found() {
    finds(Effect::BallRestitution);
}

#[test]
fn ball_friction_is_found() {
    finds(Effect::BallFriction);
}

#[test]
fn cushion_friction_is_found() {
    finds(Effect::CushionFriction);
}

#[test]
fn nap_drift_is_found() {
    finds(Effect::NapDrift);
}

#[test]
fn table_slope_is_found() {
    finds(Effect::TableSlope);
}

#[test]
fn squirt_is_found() {
    finds(Effect::Squirt);
}

#[test]
fn compliant_cushion_is_found() {
    finds(Effect::CompliantCushion);
}

#[test]
fn nothing_hidden_names_nothing() {
    // The thesis's model throughout: the data hold nothing the model lacks.
    let m = measure(
        vec![round_the_table(), cut()],
        default_model(),
        &Hidden::default(),
        11,
    );
    let o = run(&m, &Options::default()).unwrap();
    let text = report(&o);
    eprintln!("nothing hidden\n{text}");
    assert!(o.named().is_empty(), "{text}");
    assert!(!o.unexplained, "{text}");
    assert!(o.final_state.gap.rms <= 1.5 * NOISE, "{text}");
}

#[test]
fn two_hidden_effects_are_both_named() {
    let hidden = Hidden {
        effects: vec![
            (Effect::RollingResistance, vec![0.0128]),
            (Effect::TableSlope, vec![0.0008, 0.0005]),
        ],
        uncatalogued: Vec::new(),
    };
    let base = without(&[Effect::RollingResistance]);
    let m = measure(vec![round_the_table()], base, &hidden, 13);
    let o = run(&m, &Options::default()).unwrap();
    let text = report(&o);
    eprintln!("two hidden\n{text}");
    let mut named = o.named();
    named.sort();
    assert_eq!(
        named,
        vec![Effect::RollingResistance, Effect::TableSlope],
        "{text}"
    );
    let last = &o.steps.last().unwrap().fitted;
    for (effect, want) in &hidden.effects {
        let got = &last.iter().find(|f| f.effect == *effect).unwrap().values;
        for (g, w) in got.iter().zip(want) {
            assert!(
                (g - w).abs() <= 0.1 * w.abs(),
                "{}: {g} for {w}\n{text}",
                effect.id()
            );
        }
    }
    assert!(o.final_state.gap.rms <= 1.5 * NOISE, "{text}");
    assert!(!o.unexplained, "{text}");
}

#[test]
fn an_effect_outside_the_catalogue_is_unexplained_and_not_named() {
    // A ball with an off-centre mass wobbles sideways once per revolution: 3 mm, six times
    // the camera noise. No catalogue effect makes a path oscillate.
    let hidden = Hidden {
        effects: Vec::new(),
        uncatalogued: vec![Uncatalogued::Wobble { amplitude: 0.003 }],
    };
    let m = measure(vec![round_the_table()], default_model(), &hidden, 17);
    let o = run(&m, &Options::default()).unwrap();
    let text = report(&o);
    eprintln!("wobble\n{text}");
    assert!(o.named().is_empty(), "{text}");
    assert!(o.unexplained, "{text}");
    let place = o.unexplained_where.as_deref().unwrap_or("");
    assert!(place.contains("cue"), "{place}");
}

/// The per-effect cases over five more noise seeds (slow: run with `--ignored`); prints how
/// many pass, for docs/discrepancy.md.
#[test]
#[ignore]
fn seed_sweep() {
    let mut failed = Vec::new();
    for effect in Effect::ALL {
        for seed in 100..105 {
            if let Some(why) = check(&case(effect), seed) {
                failed.push(format!("{} seed {seed}: {why}", effect.id()));
            }
        }
    }
    let runs = 5 * Effect::ALL.len();
    eprintln!("seed sweep: {} of {runs} pass", runs - failed.len());
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

/// A law outside the catalogue's forms hidden in `shots` (the thesis's model otherwise): the
/// workflow names nothing, or only effects in `allowed` (the catalogue's own form of the
/// law, refitted), and a residual left significant is reported unexplained. Never a wrong
/// effect named (issue 25).
fn outside_the_catalogue(law: Uncatalogued, shots: Vec<ShotData>, allowed: &[Effect], seed: u64) {
    let hidden = Hidden {
        effects: Vec::new(),
        uncatalogued: vec![law],
    };
    let m = measure(shots, default_model(), &hidden, seed);
    let o = run(&m, &Options::default()).unwrap();
    let text = report(&o);
    eprintln!(
        "{law:?}\n{text}\ntentative: {:?}",
        o.tentative
            .iter()
            .map(|s| s.effect.id())
            .collect::<Vec<_>>()
    );
    for e in o.named() {
        assert!(allowed.contains(&e), "{law:?}: named {}\n{text}", e.id());
    }
    // The law is large enough to be seen: either it is explained to the noise by the
    // allowed effects, or it is reported.
    assert!(
        o.unexplained || o.final_state.gap.rms <= 1.5 * NOISE,
        "{text}"
    );
    if o.named().is_empty() {
        assert!(
            o.unexplained,
            "{law:?}: nothing named, nothing reported\n{text}"
        );
    }
}

#[test]
fn rolling_resistance_different_along_x_and_y_names_nothing_wrong() {
    // The first example: once "explained" by a table slope and nap drift.
    outside_the_catalogue(
        Uncatalogued::AnisotropicRolling { mu_roll_y: 0.0160 },
        vec![round_the_table()],
        &[Effect::RollingResistance],
        21,
    );
}

#[test]
fn strongly_anisotropic_rolling_resistance_names_nothing_wrong() {
    // Twice the resistance across the table as along it: no one mu_roll fits both.
    outside_the_catalogue(
        Uncatalogued::AnisotropicRolling { mu_roll_y: 0.0256 },
        vec![round_the_table()],
        &[Effect::RollingResistance],
        25,
    );
}

#[test]
fn throw_falling_with_speed_names_nothing_wrong() {
    // The second example: once "explained" by a 3e-5 table slope. One impact's throw
    // is one friction: its refit is the law's own form.
    outside_the_catalogue(
        Uncatalogued::ThrowFallingWithSpeed { mu_slow: 0.12 },
        vec![cut()],
        &[Effect::BallFriction],
        22,
    );
}

#[test]
fn rolling_resistance_rising_with_speed_names_nothing_wrong() {
    outside_the_catalogue(
        Uncatalogued::RollingRisingWithSpeed { speed: 1.0 },
        vec![round_the_table()],
        &[Effect::RollingResistance],
        23,
    );
}

#[test]
fn cushion_restitution_depending_on_the_angle_names_nothing_wrong() {
    outside_the_catalogue(
        Uncatalogued::CushionAngleRestitution { drop: 0.2 },
        vec![cushions()],
        &[
            Effect::CushionFriction,
            Effect::CushionSpeedRestitution,
            Effect::CompliantCushion,
        ],
        24,
    );
}
