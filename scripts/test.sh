#!/usr/bin/env bash
# The project's test command: formatting, lints, every test of the workspace optimised (physics
# in a debug build is ~80x slower; the `ci` profile of Cargo.toml: release with lighter
# dependencies), then 10,000 fuzz scenes, then the shot lab in headless Chromium
# (scripts/browser_tests.sh: Debian's chromium, npm's playwright-core), then the Python
# package's tests (scripts/python_tests.sh: a venv from PyPI). Needs cargo, python3, node and
# npm, and a TrueType font for
# the plots' text (DejaVu Sans: installed here from Debian's packages if the machine lacks it).
# Then the book (docs/, mdBook: installed with cargo if missing) is built and its links checked.
# Each part prints its time when it ends (docs/testing.md quotes them).
set -euo pipefail
cd "$(dirname "$0")/.."
part() {
    local name=$1 start=$SECONDS
    shift
    "$@"
    echo "== test.sh: $name took $((SECONDS - start)) s ($(disk_free) free on the target's disk)" >&2
}
# What the build leaves free on the target directory's disk, printed after each part: a clean
# build fills several GB, and a CI machine once ran out mid-way (stop 33).
disk_free() {
    local dir=${CARGO_TARGET_DIR:-target}
    [ -d "$dir" ] || dir=.
    df -h "$dir" 2>/dev/null | awk 'NR == 2 { print $4 }'
}
# The book: mdBook 0.5 is installed by cargo when missing (once per machine, into cargo's bin
# directory; no default features: no server, no search; built without optimisation, which
# halves its build and leaves a small book's rendering well under a second), then
# `mdbook build docs` (to target/book), then every relative link and anchor of the built book and
# of the README checked offline, and the architecture page's generated parts against the tree.
book() {
    local mdbook
    mdbook=$(command -v mdbook || true)
    if [ -z "$mdbook" ] || ! "$mdbook" --version | grep -q '^mdbook v0\.5\.'; then
        CARGO_PROFILE_RELEASE_OPT_LEVEL=0 \
            cargo install mdbook --locked --no-default-features --version 0.5.4
        mdbook=${CARGO_HOME:-$HOME/.cargo}/bin/mdbook
    fi
    "$mdbook" build docs
    python3 scripts/check_links.py target/book
    python3 scripts/crate_graph.py --check
}
start_all=$SECONDS
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
# What the browser and Python parts install (Debian's chromium, npm's playwright-core, a venv from
# PyPI) is mostly downloading: it runs beside the build, its output in a log printed if it fails.
prepare_log=${CARGO_TARGET_DIR:-target}/prepare.log
mkdir -p "$(dirname "$prepare_log")"
(scripts/browser_tests.sh --prepare && scripts/python_tests.sh --prepare) >"$prepare_log" 2>&1 &
prepare=$!
prepared() {
    wait "$prepare" || {
        cat "$prepare_log" >&2
        echo "test.sh: installing what the browser and Python parts need failed" >&2
        return 1
    }
}
part format cargo fmt --all -- --check
part lints cargo clippy --workspace --all-targets --profile ci -- -D warnings
part tests cargo test --workspace --profile ci
# The API documentation builds without a warning (broken or private links fail it).
# With the examples: dependencies then resolve their features as for the lints (which include
# dev-dependencies), so the lints' checked dependencies are reused, not checked again (50 s).
RUSTDOCFLAGS="-D warnings" part "API docs" \
    cargo doc --workspace --no-deps --profile ci --lib --bins --examples --quiet
part book book
# Random and hostile scenes through the scene parser and the engine, every invariant checked
# (fuzz/): a fresh seed each run, printed; failing scenes go to fuzz-failures.toml. The binary
# is the one `cargo test` built for fuzz/tests (`cargo run -p` or `cargo build` would resolve
# other features and build the engine, or rerun's dependencies, again; the results are the
# same bits either way).
part fuzz "${CARGO_TARGET_DIR:-target}/ci/snooker-fuzz" --scenes 10000
part "waiting for the installs" prepared
# The shot lab's page in a real browser (server/browser/): the binary `cargo test` built.
part browser scripts/browser_tests.sh
# The Python package (python/, built by maturin) and its tests, in a venv it makes itself.
part Python scripts/python_tests.sh
echo "== test.sh: all parts took $((SECONDS - start_all)) s" >&2
