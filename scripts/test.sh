#!/usr/bin/env bash
# The project's test command: formatting, lints, then every test of the workspace in release
# mode (physics in a debug build is ~80x slower). Needs only cargo.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo fmt --all -- --check
cargo clippy --workspace --all-targets --release -- -D warnings
cargo test --workspace --release
