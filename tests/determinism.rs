//! The same scene gives bit-identical results, through the library and through the CLI.

use snooker_scene::{self as scene, result};
use std::process::Command;

#[test]
fn same_scene_same_json() {
    let sc = scene::parse(scene::DEFAULT_SCENE, "break-off").unwrap();
    let a = snooker_engine::simulate(&sc.setup, &sc.options).unwrap();
    let b = snooker_engine::simulate(&sc.setup, &sc.options).unwrap();
    let ja = serde_json::to_string(&result::result_json(&sc, &a)).unwrap();
    let jb = serde_json::to_string(&result::result_json(&sc, &b)).unwrap();
    assert_eq!(ja, jb);
    assert!(a.events.len() > 20);
}

#[test]
fn the_cli_writes_identical_files() {
    let dir = std::env::temp_dir().join(format!("snooker-det-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut outs = Vec::new();
    for k in 0..2 {
        let out = dir.join(format!("r{k}.json"));
        let st = Command::new(env!("CARGO_BIN_EXE_snooker"))
            .args(["simulate", "--quiet", "--json"])
            .arg(&out)
            .status()
            .unwrap();
        assert!(st.success());
        outs.push(std::fs::read(&out).unwrap());
    }
    assert_eq!(outs[0], outs[1]);
    std::fs::remove_dir_all(&dir).unwrap();
}
