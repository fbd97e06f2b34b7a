//! Shots per second (`cargo bench -p snooker-batch --bench throughput`; criterion reports
//! elements/s = shots/s): 256 two-ball shots and 32 break-offs, each set on one thread and on
//! every core (issue 14's goals: at least 10^4 two-ball shots/s and 1,000 break-offs/s per
//! core). The shots vary (seeded): a cue ball and a red at random, struck towards the red at
//! 0.5-5 m/s with random tip offsets; the break-off struck at 2.5-4.5 m/s, its heading within
//! 0.01 rad of the scene file's.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use snooker_batch::{sets, simulate_many};

fn throughput(c: &mut Criterion) {
    let sets = sets::throughput_sets();
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
