//! Shared helpers of the command line's integration tests.
#![allow(dead_code)]

use std::path::PathBuf;
use std::process::{Command, Output};

/// Runs the `snooker` command with `args`.
pub fn snooker(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_snooker"))
        .args(args)
        .output()
        .unwrap()
}

/// A fresh, empty temporary directory for test `tag`.
pub fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("snooker-test-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}
