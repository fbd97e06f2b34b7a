//! The cancellation hook: a raised flag stops a plan without simulating further shots.

use snooker_planner::{Cancel, Problem, Request, plan_problem};

fn problem(cancel: &Cancel) -> Problem {
    let scene = snooker_scene::parse(
        r#"balls = [{id = "cue", pos = [1.0, 0.8]}, {id = "red", pos = [1.3, 1.3]}]"#,
        "cancel.toml",
    )
    .unwrap();
    let mut request = Request::new("red", "middle-left", [1.5, 1.2], &scene.setup.params);
    request.samples = 64;
    Problem::new(&scene, request)
        .unwrap()
        .with_cancel(cancel.clone())
}

#[test]
fn a_raised_flag_simulates_nothing() {
    let cancel = Cancel::new();
    cancel.cancel();
    let p = problem(&cancel);
    assert!(p.cancelled());
    assert!(plan_problem(&p, "cancel").is_err());
    assert_eq!(p.shots(), 0);
}

#[test]
fn raising_the_flag_mid_plan_stops_it() {
    // The uncancelled plan's count, then the same plan cancelled once it has simulated a few
    // shots: it stops far short of that count.
    let full = problem(&Cancel::new());
    plan_problem(&full, "cancel").unwrap();
    let cancel = Cancel::new();
    let p = problem(&cancel);
    std::thread::scope(|s| {
        s.spawn(|| {
            while p.shots() < 20 {
                std::thread::yield_now();
            }
            cancel.cancel();
        });
        let _ = plan_problem(&p, "cancel");
    });
    assert!(p.cancelled());
    // Shots already under way when the flag went up finish; nothing after them starts.
    assert!(
        p.shots() < full.shots() / 2,
        "{} of {}",
        p.shots(),
        full.shots()
    );
}
