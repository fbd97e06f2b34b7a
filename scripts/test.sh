#!/usr/bin/env bash
# The project's test command: formatting, every test of the workspace optimised (physics in a
# debug build is ~80x slower; the `ci` profile of Cargo.toml: release with lighter
# dependencies), then 10,000 fuzz scenes, then the shot lab in headless Chromium
# (scripts/browser_tests.sh: Debian's chromium, npm's playwright-core), then the Python
# package's tests (scripts/python_tests.sh: a venv from PyPI). Beside the tests, in a lane of
# their own: the lints, the API docs, the book (docs/, mdBook: installed with cargo if
# missing; its links checked) and the Python crate's lints. Needs cargo, python3, node and npm,
# and a TrueType font for the plots' text (DejaVu Sans: installed here from Debian's packages
# if the machine lacks it). Each part prints its time when it ends (docs/testing.md quotes
# them).
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
target=${CARGO_TARGET_DIR:-target}
mkdir -p "$target"
# Two lanes share the two cores. The tests' build and run (the long one: about 18 minutes of a
# clean run) leave a core idle for long stretches: one crate waiting on another, a test binary
# on one thread. The checks lane fills them: the lints, the API docs, the book and the Python
# crate's lints, in a target directory of their own (cargo locks its target directory for a whole
# `cargo test`), at a lower priority so that the tests' critical path keeps the cores it needs.
# Its output goes to a log, printed when it fails and its parts' times when it is done. A third
# job installs what the browser and Python parts need (Debian's chromium, npm's playwright-core,
# the venv's packages from PyPI): mostly downloading.
checks_dir=$(realpath -m "$target")/checks
checks_log=$target/checks.log
checks() {
    renice -n 10 -p "$BASHPID" >/dev/null 2>&1 || true
    export CARGO_TARGET_DIR=$checks_dir
    part lints cargo clippy --workspace --all-targets --profile ci -- -D warnings
    # The API documentation builds without a warning (broken or private links fail it). With
    # the examples: dependencies then resolve their features as for the lints (which include
    # dev-dependencies), so the lints' checked dependencies are reused, not checked again.
    RUSTDOCFLAGS="-D warnings" part "API docs" \
        cargo doc --workspace --no-deps --profile ci --lib --bins --examples --quiet
    part book book
    part "Python lints" scripts/python_tests.sh --lints
}
# A part failing ends the command: the jobs beside it, and what they started, are stopped.
kill_tree() {
    local p
    for p in "$@"; do
        # shellcheck disable=SC2046 # one pid per word
        kill_tree $(pgrep -P "$p" || true)
        kill "$p" 2>/dev/null || true
    done
}
trap 'status=$?; [ "$status" -eq 0 ] || kill_tree $(jobs -p)' EXIT
(checks) >"$checks_log" 2>&1 &
checks_job=$!
prepare_log=$target/prepare.log
(scripts/browser_tests.sh --prepare && scripts/python_tests.sh --prepare) >"$prepare_log" 2>&1 &
prepare=$!
# Waits for a background job; prints its log if it failed.
finished() {
    local job=$1 log=$2 what=$3
    wait "$job" || {
        cat "$log" >&2
        echo "test.sh: $what failed" >&2
        return 1
    }
}
# The checks lane's parts and times (they ran beside the tests).
checked() {
    finished "$checks_job" "$checks_log" "the checks (lints, API docs, book, Python lints)"
    sed -n 's/^== test.sh: \(.*\)$/== test.sh: (beside the tests) \1/p' "$checks_log" >&2
}
part format cargo fmt --all -- --check
part tests cargo test --workspace --profile ci
# Random and hostile scenes through the scene parser and the engine, every invariant checked
# (fuzz/): a fresh seed each run, printed; failing scenes go to fuzz-failures.toml. The binary
# is the one `cargo test` built for fuzz/tests (`cargo run -p` or `cargo build` would resolve
# other features and build the engine, or rerun's dependencies, again; the results are the
# same bits either way).
part fuzz "$target/ci/snooker-fuzz" --scenes 10000
part "waiting for the installs" finished "$prepare" "$prepare_log" \
    "installing what the browser and Python parts need"
# The shot lab's page in a real browser (server/browser/): the binary `cargo test` built.
part browser scripts/browser_tests.sh
# The Python package (python/, built by maturin) and its tests, in a venv it makes itself.
part Python scripts/python_tests.sh --tests
part "waiting for the checks" checked
echo "== test.sh: all parts took $((SECONDS - start_all)) s" >&2
