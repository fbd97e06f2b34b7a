#!/usr/bin/env bash
# The Python package's part of the test command: a venv (target/py-venv) with what the tests
# need from PyPI (pytest, numpy, pyarrow, ray, gymnasium), the package installed into it as a
# user installs it, `pip install ./python` (maturin builds the wheel, sharing the workspace's
# target directory and, here, its `ci` profile, so neither the engine crates nor their
# dependencies are built twice), its formatting and lints, then its tests (python/tests)
# against the command line built by
# `cargo test --workspace --profile ci` (target/ci/snooker). The target directory is
# $CARGO_TARGET_DIR when set, as cargo's.
#   scripts/python_tests.sh             # everything: lints, wheel, tests
#   scripts/python_tests.sh --prepare   # the venv and its packages only
#   scripts/python_tests.sh --lints     # the Rust crate's formatting and lints only (no venv)
#   scripts/python_tests.sh --tests     # the wheel and the tests only
# The test command runs `--lints` beside the build (with the workspace's lints, in their own
# target directory) and `--tests` at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-all}
case $mode in
all | --prepare | --lints | --tests) ;;
*)
    echo "python_tests.sh: unknown argument '$mode' (--prepare, --lints, --tests or none)" >&2
    exit 2
    ;;
esac
# The crate's formatting and lints. pyo3's build script asks `PYO3_PYTHON` (else python3) for
# the interpreter's configuration; abi3 makes the lints the same for any CPython 3.9+.
lints() {
    cargo fmt --manifest-path python/Cargo.toml -- --check
    # The `ci` profile (python/Cargo.toml), as `cargo test` uses.
    cargo clippy --manifest-path python/Cargo.toml --profile ci --all-targets -- -D warnings
}
if [ "$mode" = --lints ]; then
    lints
    exit 0
fi
target=$(realpath -m "${CARGO_TARGET_DIR:-target}")
# pip through the venv's own python: a venv's bin/pip scripts name the path the venv was made at,
# so a venv copied with target/ (from another clone) would install into the original.
venv=$target/py-venv
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
# No pip cache: ray's and pyarrow's wheels are hundreds of MB, and the venv keeps them installed.
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check --no-cache-dir \
    pytest numpy pyarrow ray gymnasium
# `--prepare`: only the venv and what it needs from PyPI (the test command runs this beside the
# build: it is mostly downloading).
[ "$mode" = --prepare ] && exit 0
export CARGO_TARGET_DIR=$target PYO3_PYTHON=$venv/bin/python
if [ "$mode" = all ]; then lints; fi
# The wheel on the `ci` profile, as `cargo test` used: what it built is reused from the target
# directory where the features agree, not built again in release (time, and the disk of a
# clean CI machine, which the release build once filled).
MATURIN_PEP517_ARGS="--profile ci" "$venv/bin/python" -m pip install --quiet \
    --disable-pip-version-check --no-cache-dir --force-reinstall --no-deps ./python
SNOOKER_CLI=$target/ci/snooker RAY_AUTH_MODE=disabled \
    "$venv/bin/python" -m pytest -q python/tests
