//! The sets of shots issue 14's throughput is measured on (`benches/throughput.rs`,
//! `examples/profile.rs`), seeded so that every run measures the same shots: 256 two-ball shots
//! (a cue ball and a red anywhere, struck towards the red) and 32 break-offs.

use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
use snooker_scene::{BallSpec, CueSpec, Scene, SceneFile};

/// The two sets, named: "two-ball shots" (256) and "break-offs" (32).
pub fn throughput_sets() -> [(&'static str, Vec<Scene>); 2] {
    let mut rng = ChaCha8Rng::seed_from_u64(14);
    let two = (0..256).map(|_| two_ball(&mut rng)).collect();
    let breaks = (0..32).map(|_| break_off(&mut rng)).collect();
    [("two-ball shots", two), ("break-offs", breaks)]
}

/// A cue ball and a red at random, the cue ball struck towards the red (within 0.02 rad) at
/// 0.5-5 m/s with a random tip offset (up to 10 mm each way).
fn two_ball(rng: &mut ChaCha8Rng) -> Scene {
    loop {
        let c: [f64; 2] = [rng.random_range(0.3..3.2), rng.random_range(0.3..1.5)];
        let o: [f64; 2] = [rng.random_range(0.3..3.2), rng.random_range(0.3..1.5)];
        if (c[0] - o[0]).hypot(c[1] - o[1]) < 0.1 {
            continue;
        }
        let aim = (o[1] - c[1]).atan2(o[0] - c[0]) + rng.random_range(-0.02..0.02);
        let speed = rng.random_range(0.5..5.0);
        let offset = [rng.random_range(-0.01..0.01), rng.random_range(-0.01..0.01)];
        return SceneFile::new()
            .with_ball(BallSpec::at("cue", c))
            .with_ball(BallSpec::at("red", o))
            .with_strike(CueSpec::new("cue", speed, aim).with_offset(offset))
            .build("two-ball")
            .expect("a generated scene is valid");
    }
}

/// The break-off struck at 2.5-4.5 m/s, its heading within 0.01 rad of the scene file's.
fn break_off(rng: &mut ChaCha8Rng) -> Scene {
    let speed = rng.random_range(2.5..4.5);
    let aim = -0.006 + rng.random_range(-0.01..0.01);
    SceneFile::new()
        .with_layout("break-off")
        .with_strike(
            CueSpec::new("cue", speed, aim)
                .with_offset([0.004, 0.0])
                .with_elevation(0.1),
        )
        .build("break-off")
        .expect("a generated scene is valid")
}
