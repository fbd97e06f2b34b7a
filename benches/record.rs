//! Export time of a Rerun recording: the break-off (the built-in default scene) at the default
//! 240 Hz, from the simulated shot to the `.rrd` bytes in memory, and to a file on disk.

use criterion::{Criterion, criterion_group, criterion_main};
use snooker::record::{self, RecordOptions};
use snooker_scene as scene;
use std::hint::black_box;

fn export(c: &mut Criterion) {
    let scene = scene::parse(scene::DEFAULT_SCENE, scene::DEFAULT_SCENE_FILE).unwrap();
    let shot = snooker_engine::simulate(&scene.setup, &scene.options).unwrap();
    let opts = RecordOptions::default();
    let size = record::encode(&scene, &shot, &opts).unwrap().len();
    eprintln!(
        "break-off: {:.3} s simulated, {} events, recording {:.2} MB",
        shot.duration,
        shot.events.len(),
        size as f64 / 1e6
    );
    let mut group = c.benchmark_group("record");
    group.sample_size(20);
    group.bench_function("break-off 240 Hz to memory", |b| {
        b.iter(|| record::encode(black_box(&scene), black_box(&shot), &opts).unwrap())
    });
    let path = std::env::temp_dir().join(format!("snooker-bench-{}.rrd", std::process::id()));
    group.bench_function("break-off 240 Hz to file", |b| {
        b.iter(|| {
            let bytes = record::encode(black_box(&scene), black_box(&shot), &opts).unwrap();
            std::fs::write(&path, bytes).unwrap();
        })
    });
    group.finish();
    let _ = std::fs::remove_file(&path);
}

criterion_group!(benches, export);
criterion_main!(benches);
