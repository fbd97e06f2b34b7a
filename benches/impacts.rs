//! Time per impact of each Mathavan model at the default tolerance (results converged to
//! better than 1e-6 relative, see tests/impact_models.rs). Run with `cargo bench --bench impacts`.

use criterion::{Criterion, criterion_group, criterion_main};
use snooker_engine::impact::ball_ball::mathavan as bb;
use snooker_engine::impact::cushion::mathavan as cush;
use snooker_engine::{BallState, Motion, Params, Vec3};
use std::hint::black_box;

fn impacts(c: &mut Criterion) {
    let p = Params::default();
    let r = p.ball_radius;
    // A rolling cue ball with sidespin meeting a red at a 30-degree cut, 2 m/s.
    let cut = 30f64.to_radians();
    let cue = BallState {
        pos: Vec3::new(0.0, 0.0, r),
        vel: Vec3::new(2.0, 0.0, 0.0),
        spin: Vec3::new(0.0, 2.0 / r, 1.0 / r),
        motion: Motion::Rolling,
    };
    let red = BallState::at_rest(2.0 * r * cut.cos(), 2.0 * r * cut.sin(), r);
    c.bench_function(
        "ball-ball mathavan (2 m/s, 30 deg cut, top and side)",
        |b| b.iter(|| bb::resolve(black_box(&cue), black_box(&red), &p).unwrap()),
    );
    // A rolling ball into a cushion at 45 degrees, 1 m/s.
    let a = 45f64.to_radians();
    let v = Vec3::new(a.cos(), -a.sin(), 0.0);
    let ball = BallState {
        pos: Vec3::new(1.0, p.cushion_contact_distance(), r),
        vel: v,
        spin: Vec3::z().cross(&v) / r,
        motion: Motion::Rolling,
    };
    c.bench_function("cushion mathavan (1 m/s, 45 deg, rolling)", |b| {
        b.iter(|| cush::resolve(black_box(&ball), Vec3::y(), &p).unwrap())
    });
}

criterion_group!(benches, impacts);
criterion_main!(benches);
