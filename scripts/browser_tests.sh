#!/usr/bin/env bash
# The shot lab in a real browser (server/browser/lab.test.mjs): headless Chromium from Debian's
# packages (installed here when missing, with chromium-driver), driven by playwright-core
# (pinned by server/browser/package-lock.json; it never downloads a browser of its own),
# against `snooker serve` on a loopback port. Needs node and npm.
#   scripts/browser_tests.sh                          # as the test command runs it
#   scripts/browser_tests.sh --screenshots docs/img   # and writes the screenshots
#   scripts/browser_tests.sh --prepare                # installs what it needs, runs nothing
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -x /usr/bin/chromium ]; then
    SUDO=$([ "$(id -u)" -eq 0 ] || echo sudo)
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq --no-install-recommends chromium chromium-driver
fi
(cd server/browser && npm ci --no-audit --no-fund --silent)
# `--prepare`: only the browser and playwright-core (the test command runs this beside the
# build: it is mostly downloading).
[ "${1:-}" = --prepare ] && exit 0
bin="${CARGO_TARGET_DIR:-target}/ci/snooker"
if [ ! -x "$bin" ]; then
    cargo build --profile ci --bin snooker
fi
SNOOKER_BIN="$(realpath "$bin")" node server/browser/lab.test.mjs "$@"
