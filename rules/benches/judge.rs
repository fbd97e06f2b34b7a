//! What judging a stroke costs next to simulating it (the break-building player judges
//! thousands of candidate strokes per decision): `Frame::judge` on the break-off (legal, 154
//! events), on a foul that leaves the cue ball on the table (the snookered test from where it
//! lies) and on a foul that leaves it in hand (the test from every point of the D on a 5 mm
//! grid, stopping at the first point not snookered); the simulation of the break-off for scale.

use criterion::{Criterion, criterion_group, criterion_main};
use snooker_engine::{Cue, simulate};
use snooker_rules::Frame;
use std::hint::black_box;
use std::path::Path;

fn frame(name: &str) -> (Frame, snooker_engine::Shot) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("tests/frames/{name}.toml"));
    let f = snooker_rules::load(&path).unwrap();
    let shot = simulate(&f.scene.setup, &f.scene.options).unwrap();
    (f.frame, shot)
}

fn bench(c: &mut Criterion) {
    let break_off = Frame::break_off();
    let strike = Cue {
        speed: 3.4,
        aim: -0.006,
        offset: [0.004, 0.0],
        elevation: 0.1,
    };
    let setup = break_off.setup(&strike).unwrap();
    let shot = simulate(&setup, break_off.options()).unwrap();
    c.bench_function("judge the break-off", |b| {
        b.iter(|| black_box(&break_off).judge(black_box(&shot)).unwrap())
    });
    let (f, s) = frame("free_ball_awarded");
    c.bench_function("judge a foul, cue ball on the table", |b| {
        b.iter(|| black_box(&f).judge(black_box(&s)).unwrap())
    });
    let (f, s) = frame("cue_ball_potted");
    c.bench_function("judge a foul, cue ball in hand", |b| {
        b.iter(|| black_box(&f).judge(black_box(&s)).unwrap())
    });
    c.bench_function("simulate the break-off", |b| {
        b.iter(|| simulate(black_box(&setup), break_off.options()).unwrap())
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
