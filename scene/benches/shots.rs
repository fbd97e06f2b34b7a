//! Whole-shot simulation time: the break-off (22 balls) and a two-ball shot.
//! Run with `cargo bench -p snooker-scene --bench shots`; medians are quoted in docs/performance.md.

use criterion::{Criterion, criterion_group, criterion_main};
use snooker_scene as scene;
use std::hint::black_box;
use std::path::Path;

fn load(name: &str) -> scene::Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../scenes")
        .join(name);
    scene::load(&path).expect("scene")
}

fn shots(c: &mut Criterion) {
    for (label, sc) in [
        ("break-off (22 balls)", load("break-off.toml")),
        ("two-ball cut-30", load("cut-30.toml")),
    ] {
        c.bench_function(label, |b| {
            b.iter(|| snooker_engine::simulate(black_box(&sc.setup), &sc.options).unwrap())
        });
    }
}

criterion_group!(benches, shots);
criterion_main!(benches);
