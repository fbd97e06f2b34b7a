//! Time per impact of each Mathavan model at the default tolerance (results converged to
//! better than 1e-6 relative, see engine/tests/impact_models.rs). Run with
//! `cargo bench -p snooker-engine --bench impacts`.

use criterion::{Criterion, criterion_group, criterion_main};
use snooker_engine::impact::ball_ball::mathavan as bb;
use snooker_engine::impact::cushion::{compliant, mathavan as cush};
use snooker_engine::impact::incoming;
use snooker_engine::{Params, Vec3};
use std::hint::black_box;

fn impacts(c: &mut Criterion) {
    let p = Params::default();
    let (cue, red) = incoming::typical_ball_ball(&p);
    c.bench_function(
        "ball-ball mathavan (2 m/s, 30 deg cut, top and side)",
        |b| b.iter(|| bb::resolve(black_box(&cue), black_box(&red), &p).unwrap()),
    );
    let ball = incoming::typical_cushion(&p);
    c.bench_function("cushion mathavan (1 m/s, 45 deg, rolling)", |b| {
        b.iter(|| cush::resolve(black_box(&ball), Vec3::y(), &p).unwrap())
    });
    // A hard impact, beyond the compliant cushion's travel: rolling square on at 3 m/s.
    let hard = incoming::cushion(3.0, std::f64::consts::FRAC_PI_2, 1.0, 0.0, &p);
    c.bench_function("cushion mathavan (3 m/s, square on, rolling)", |b| {
        b.iter(|| cush::resolve(black_box(&hard), Vec3::y(), &p).unwrap())
    });
    c.bench_function("cushion compliant (3 m/s, square on, rolling)", |b| {
        b.iter(|| compliant::resolve(black_box(&hard), Vec3::y(), &p).unwrap())
    });
}

criterion_group!(benches, impacts);
criterion_main!(benches);
