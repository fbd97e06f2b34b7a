#!/usr/bin/env bash
# The Python package's part of the test command: a venv (target/py-venv) with what the tests
# need from PyPI (pytest, numpy, pyarrow, ray, gymnasium), the package installed into it as a
# user installs it, `pip install ./python` (maturin builds the wheel, sharing the workspace's target
# directory, so the engine crates are not built twice), its formatting and lints, then its tests (python/tests) against the command line built by
# `cargo test --workspace --profile ci` (target/ci/snooker). The target directory is
# $CARGO_TARGET_DIR when set, as cargo's.
set -euo pipefail
cd "$(dirname "$0")/.."
target=$(realpath -m "${CARGO_TARGET_DIR:-target}")
# pip through the venv's own python: a venv's bin/pip scripts name the path the venv was made at,
# so a venv copied with target/ (from another clone) would install into the original.
venv=$target/py-venv
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check pytest numpy pyarrow ray gymnasium
export CARGO_TARGET_DIR=$target PYO3_PYTHON=$venv/bin/python
cargo fmt --manifest-path python/Cargo.toml -- --check
cargo clippy --manifest-path python/Cargo.toml --release --all-targets -- -D warnings
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check --force-reinstall --no-deps ./python
SNOOKER_CLI=$target/ci/snooker RAY_AUTH_MODE=disabled \
    "$venv/bin/python" -m pytest -q python/tests
