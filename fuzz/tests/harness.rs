//! The fuzz harness as a user runs it: a seeded run passes, and its digest (a hash of every
//! result) does not depend on the number of threads. (Building this test also builds the
//! `snooker-fuzz` binary with the workspace's features, which the test command then runs on
//! 10,000 scenes of a fresh seed.)

use std::process::Command;

/// Runs 300 scenes of seed 7 on `threads` threads; returns the digest line.
fn digest(threads: &str) -> String {
    let out_file = std::env::temp_dir().join(format!(
        "snooker-fuzz-test-{threads}-{}.toml",
        std::process::id()
    ));
    let out = Command::new(env!("CARGO_BIN_EXE_snooker-fuzz"))
        .args(["--seed", "7", "--scenes", "300", "--out"])
        .arg(&out_file)
        .env("RAYON_NUM_THREADS", threads)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("(300 scenes), 0 failing"), "{stdout}");
    let _ = std::fs::remove_file(&out_file);
    let line = stdout
        .lines()
        .find(|l| l.starts_with("digest of the results: "));
    line.unwrap_or_else(|| panic!("no digest in {stdout}"))
        .to_string()
}

#[test]
fn a_seeded_run_passes_with_the_same_digest_on_one_thread_or_two() {
    assert_eq!(digest("1"), digest("2"));
}
