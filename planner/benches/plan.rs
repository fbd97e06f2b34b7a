//! Wall time of a whole plan (`cargo bench -p snooker-planner --bench plan`): the thesis's
//! chapter 7 position to 5 mm and to 1 mm (issue 13's goals: a median of at most 1 s and 2 s
//! on 2 cores), with 64 noise samples per shot and the default three alternatives.

use criterion::{Criterion, criterion_group, criterion_main};
use snooker_planner::{Request, plan};
use std::time::Duration;

fn chapter7(c: &mut Criterion) {
    let text = include_str!("../../scenes/chapter7-example.toml");
    let scene = snooker_scene::parse(text, "chapter7-example.toml").expect("scene");
    let mut g = c.benchmark_group("plan");
    g.sample_size(10).measurement_time(Duration::from_secs(20));
    for (name, tol) in [("chapter7 to 5 mm", 0.005), ("chapter7 to 1 mm", 0.001)] {
        let mut req = Request::new("red", "middle-left", [1.25, 0.0262], &scene.setup.params);
        req.tolerance = tol;
        req.samples = 64;
        let shots = plan(&scene, req.clone()).expect("plan").shots_simulated;
        eprintln!("{name}: {shots} shots simulated");
        g.bench_function(name, |b| {
            b.iter(|| plan(&scene, req.clone()).expect("plan"))
        });
    }
    g.finish();
}

criterion_group!(benches, chapter7);
criterion_main!(benches);
