//! The cross-check against rapier on the validation scene set, asserting the verdicts of the
//! report (tolerances derived in `snooker_validation::tolerance`, explained in
//! docs/validation.md), at the time step the convergence study chose.
//!
//! Runtime: about 25 s in release on 2 cores for the whole set.

use snooker_engine::{Setup, simulate};
use snooker_validation::compare::{Scope, compare};
use snooker_validation::crosscheck::{
    self, DEFAULT_DT, Outcome, RESTING_APPROACH, RunReport, SceneSpec,
};
use snooker_validation::rapier_run;
use snooker_validation::record::Record;
use snooker_validation::scenes::{BUILTIN, ImpactModels};
use snooker_validation::shapes::jaw_solid;
use snooker_validation::tolerance::{Budget, allowances};

fn spec(file: &str) -> SceneSpec {
    let text = BUILTIN
        .iter()
        .find(|(f, _)| *f == file)
        .map(|(_, t)| *t)
        .unwrap_or_else(|| panic!("no scene {file}"));
    let s = snooker_scene::parse(text, file).expect("validation scene parses");
    SceneSpec {
        name: s.name,
        setup: s.setup,
        options: s.options,
    }
}

fn describe(r: &RunReport) -> String {
    format!("{:#?}", r)
}

/// Runs every scene whose file name starts with one of `prefixes` and asserts its verdicts.
fn assert_scenes_pass(prefixes: &[&str]) {
    let mut compared = 0;
    for (file, _) in BUILTIN
        .iter()
        .filter(|(f, _)| prefixes.iter().any(|p| f.starts_with(p)))
    {
        for r in crosscheck::check_scene(&spec(file), DEFAULT_DT) {
            match &r.outcome {
                Outcome::Compared {
                    comparison,
                    rapier_finished,
                    ..
                } => {
                    compared += 1;
                    assert!(*rapier_finished, "{file}: rapier's balls did not stop");
                    assert!(comparison.sequence_match, "{file}: {}", describe(&r));
                    assert!(!comparison.figures.is_empty(), "{file}: nothing compared");
                    assert!(r.pass(), "{file}: {}", describe(&r));
                }
                // The frictional models are not in the engine yet: skipped, never faked. Once
                // they exist the same run is compared and must pass.
                Outcome::Skipped { reason } => {
                    assert_eq!(r.models, ImpactModels::Mathavan, "{file}: {reason}");
                    assert!(ImpactModels::Mathavan.models().is_err());
                }
                Outcome::Failed { reason } => panic!("{file}: {reason}"),
            }
        }
    }
    assert!(compared > 0, "no scene matched {prefixes:?}");
}

#[test]
fn strikes_on_the_open_table_agree() {
    assert_scenes_pass(&["stun", "screw", "follow", "sidespin"]);
}

#[test]
fn cushion_impacts_agree() {
    assert_scenes_pass(&["cushion-"]);
}

#[test]
fn ball_ball_impacts_and_the_combination_agree() {
    assert_scenes_pass(&["head-on", "cut-", "combination"]);
}

#[test]
fn break_off_first_impact_agrees() {
    let r = crosscheck::check(
        &spec("break-off.toml"),
        ImpactModels::Frictionless,
        DEFAULT_DT,
    );
    let Outcome::Compared { comparison, .. } = &r.outcome else {
        panic!("{}", describe(&r));
    };
    assert_eq!(comparison.compared, 1, "only the first impact, on the pack");
    assert!(comparison.sequence_ours[0].starts_with("cue-red"));
    assert!(r.pass(), "{}", describe(&r));
    // The outcome statistics are measured against an ensemble of our engine's shots.
    assert_eq!(r.statistics.len(), 5);
    assert!(r.statistics.iter().all(|s| s.ours_min <= s.ours_max));
}

/// Our engine run on `ours_setup`, rapier on `spec`'s setup, compared with the tolerances.
fn compare_with_altered_engine(spec: &SceneSpec, ours_setup: &Setup) -> bool {
    let dt = DEFAULT_DT;
    let cfg = crosscheck::world_config(ImpactModels::Frictionless, dt);
    let window = 2.0 * dt;
    // The frictionless limit on both sides, whatever the scene's default models.
    let mut ours_setup = ours_setup.clone();
    ours_setup.models = ImpactModels::Frictionless.models().unwrap();
    let shot = simulate(&ours_setup, &spec.options).unwrap();
    let ours = Record::from_shot(&shot).normalised(window, RESTING_APPROACH);
    let run = rapier_run::run(&spec.setup, &cfg, shot.duration + 5.0);
    let rapier = run.record.normalised(window, RESTING_APPROACH);
    let p = spec.setup.params;
    let budget = Budget {
        dt,
        sink: run.sink,
        friction: false,
        level_cushions: true,
        nose_radius: jaw_solid(&p, 0.010, cfg.cushion_contact).0,
        params: p,
    };
    compare(
        &ours,
        &rapier,
        &allowances(&ours, &budget),
        &Scope::default(),
    )
    .pass()
}

#[test]
fn the_tolerances_catch_a_two_percent_error_in_our_engine() {
    // The same comparison passes as is, and fails when our engine's restitution or rolling
    // resistance is off by 2%: the tolerances are tight enough to see such an error.
    for (file, alter) in [
        (
            "cushion-45.toml",
            &(|s: &mut Setup| s.params.e_cushion *= 0.98) as &dyn Fn(&mut Setup),
        ),
        ("head-on-roll.toml", &|s: &mut Setup| {
            s.params.e_ball *= 0.98
        }),
        ("stun.toml", &|s: &mut Setup| s.params.mu_roll *= 1.02),
    ] {
        let sp = spec(file);
        assert!(compare_with_altered_engine(&sp, &sp.setup), "{file} as is");
        let mut altered = sp.setup.clone();
        alter(&mut altered);
        assert!(
            !compare_with_altered_engine(&sp, &altered),
            "{file} altered"
        );
    }
}
