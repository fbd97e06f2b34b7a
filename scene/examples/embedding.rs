//! Embedding the engine in a Rust program: a scene file read and simulated, then a scene built
//! in code with the typed scene builder. The book's "Embedding" page (docs/embedding.md) shows
//! this file as it is, and `tests/docs.rs` runs it, so the page cannot go out of date.
//!
//! Run it with `cargo run --release -p snooker-scene --example embedding`.

use snooker_engine::{EventKind, simulate};
use snooker_scene::{BallSpec, CueSpec, SceneFile};

/// Simulates a scene file, then a scene built in code, and checks what they do.
pub fn main() -> Result<(), Box<dyn std::error::Error>> {
    // 1. A scene file: parsed and checked (an error names the file, the key and the reason),
    //    the cue strike already applied. `snooker_scene::load(path)` reads it from disk.
    let text = include_str!("../../scenes/cut-30.toml");
    let scene = snooker_scene::parse(text, "scenes/cut-30.toml")?;
    let shot = simulate(&scene.setup, &scene.options)?;
    for e in &shot.events {
        println!("{:.4} s {} {:?}", e.t, e.kind.name(), e.balls);
    }
    // The exact state of any ball at any time, from the closed-form laws.
    let red = shot.tracks[1].state_at(0.5, &shot.params);
    println!(
        "red at 0.5 s: ({:.3}, {:.3}) m, {}",
        red.pos.x,
        red.pos.y,
        red.motion.name()
    );
    // The JSON result of `snooker simulate --json` (formats.md, "Result"), as typed values.
    let doc = snooker_scene::result::result_record(&scene, &shot);
    let json = serde_json::to_string(&doc)?;
    assert!(json.starts_with("{\"scene\":\"cut-30\""));

    // 2. A scene built in code: the same keys as a file, checked as a file is. A screw shot on
    //    the full-size table (x along it, m): the cue ball struck at 3 m/s along +x, the tip
    //    11 mm below centre, into a red 0.3 m away.
    let file = SceneFile::new()
        .with_name("screw-back")
        .with_ball(BallSpec::at("cue", [0.7, 0.889]))
        .with_ball(BallSpec::at("red", [1.0, 0.889]))
        .with_strike(CueSpec::new("cue", 3.0, 0.0).with_offset([0.0, -0.011]));
    println!("{}", file.to_toml()); // the same scene as a file, every number to the bit
    let scene = file.build("screw-back")?;
    let shot = simulate(&scene.setup, &scene.options)?;
    let hit = shot.events.iter().find(|e| e.kind == EventKind::BallBall);
    let hit = hit.ok_or("the cue ball should reach the red")?;
    // Screw: after the full hit the cue ball comes back past where it met the red.
    let end = shot.final_states();
    let r = shot.params.ball_radius;
    println!(
        "hit at {:.3} s; cue ball ends at x = {:.3} m",
        hit.t, end[0].pos.x
    );
    assert!(end[0].pos.x < 1.0 - 2.0 * r);
    // Every invariant the engine promises (no overlap, the energy bound, balls on the table,
    // events in order), checked.
    let violations = snooker_engine::audit::audit(&scene.setup, &shot);
    assert!(violations.is_empty(), "{violations:?}");
    Ok(())
}
