#!/usr/bin/env bash
# The project's test command: formatting, lints, every test of the workspace optimised (physics
# in a debug build is ~80x slower; the `ci` profile of Cargo.toml: release with lighter
# dependencies), then 10,000 fuzz scenes, then the Python package's tests
# (scripts/python_tests.sh: a venv from PyPI). Needs cargo, python3, and a TrueType font for
# the plots' text (DejaVu Sans: installed here from Debian's packages if the machine lacks it).
set -euo pipefail
cd "$(dirname "$0")/.."
font=""
for f in /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf /usr/share/fonts/TTF/DejaVuSans.ttf \
    /usr/share/fonts/dejavu/DejaVuSans.ttf; do
    [ -f "$f" ] && font=$f
done
if [ -z "$font" ]; then
    if command -v apt-get >/dev/null; then
        SUDO=$([ "$(id -u)" -eq 0 ] || echo sudo)
        $SUDO apt-get update -qq
        $SUDO apt-get install -y -qq --no-install-recommends fonts-dejavu-core
    else
        echo "warning: no DejaVu Sans font and no apt-get: the plot tests will fail" >&2
    fi
fi
cargo fmt --all -- --check
cargo clippy --workspace --all-targets --profile ci -- -D warnings
cargo test --workspace --profile ci
# The API documentation builds without a warning (broken or private links fail it).
RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps --profile ci --quiet
# Random and hostile scenes through the scene parser and the engine, every invariant checked
# (fuzz/): a fresh seed each run, printed; failing scenes go to fuzz-failures.toml. The binary
# is the one `cargo test` built for fuzz/tests (`cargo run -p` or `cargo build` would resolve
# other features and build the engine, or rerun's dependencies, again; the results are the
# same bits either way).
"${CARGO_TARGET_DIR:-target}/ci/snooker-fuzz" --scenes 10000
# The Python package (python/, built by maturin) and its tests, in a venv it makes itself.
scripts/python_tests.sh
