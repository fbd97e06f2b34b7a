//! Shots per second (`cargo bench -p snooker-batch --bench throughput`; criterion reports
//! elements/s = shots/s): 256 two-ball shots and 32 break-offs, each set on one thread and on
//! every core (issue 14's goals: at least 10^4 two-ball shots/s and 1,000 break-offs/s per
//! core). The shots vary (seeded): a cue ball and a red at random, struck towards the red at
//! 0.5-5 m/s with random tip offsets; the break-off struck at 2.5-4.5 m/s, its heading within
//! 0.01 rad of the scene file's.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
use snooker_batch::simulate_many;
use snooker_scene::{Scene, parse_json};

fn two_ball(rng: &mut ChaCha8Rng) -> Scene {
    loop {
        let c: [f64; 2] = [rng.random_range(0.3..3.2), rng.random_range(0.3..1.5)];
        let o: [f64; 2] = [rng.random_range(0.3..3.2), rng.random_range(0.3..1.5)];
        if (c[0] - o[0]).hypot(c[1] - o[1]) < 0.1 {
            continue;
        }
        let aim = (o[1] - c[1]).atan2(o[0] - c[0]) + rng.random_range(-0.02..0.02);
        let text = format!(
            r#"{{"balls": [{{"id": "cue", "pos": [{}, {}]}}, {{"id": "red", "pos": [{}, {}]}}],
                "cue": {{"ball": "cue", "speed": {}, "aim": {aim}, "offset": [{}, {}]}}}}"#,
            c[0],
            c[1],
            o[0],
            o[1],
            rng.random_range(0.5..5.0),
            rng.random_range(-0.01..0.01),
            rng.random_range(-0.01..0.01),
        );
        return parse_json(&text, "two-ball").expect("scene");
    }
}

fn break_off(rng: &mut ChaCha8Rng) -> Scene {
    let text = format!(
        r#"{{"layout": "break-off", "cue": {{"ball": "cue", "speed": {}, "aim": {},
             "offset": [0.004, 0.0], "elevation": 0.1}}}}"#,
        rng.random_range(2.5..4.5),
        -0.006 + rng.random_range(-0.01..0.01),
    );
    parse_json(&text, "break-off").expect("scene")
}

fn throughput(c: &mut Criterion) {
    let mut rng = ChaCha8Rng::seed_from_u64(14);
    let sets: [(&str, Vec<Scene>); 2] = [
        (
            "two-ball shots",
            (0..256).map(|_| two_ball(&mut rng)).collect(),
        ),
        ("break-offs", (0..32).map(|_| break_off(&mut rng)).collect()),
    ];
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut g = c.benchmark_group("throughput");
    g.sample_size(20);
    for (name, scenes) in &sets {
        g.throughput(Throughput::Elements(scenes.len() as u64));
        for threads in [1, cores] {
            g.bench_function(format!("{name}, {threads} thread(s)"), |b| {
                b.iter(|| simulate_many(scenes, Some(threads), || {}).expect("pool"))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, throughput);
criterion_main!(benches);
