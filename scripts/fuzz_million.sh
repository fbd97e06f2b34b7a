#!/usr/bin/env bash
# The 10^6-scene fuzz run (issue 11) in 20 parts of 50,000 (the same scenes as one run: each
# scene has its own generator), resumable: a finished part is skipped. Logs, failures and a
# `.done` marker per part go to DIR. Then: scripts/fuzz_report.py DIR COMMIT.
# Usage: scripts/fuzz_million.sh DIR [SEED]   (about 1 minute per part on 2 cores, at 037825d;
# the binary is built in $CARGO_TARGET_DIR if set, as cargo does)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=$(realpath -m "${1:?usage: fuzz_million.sh DIR [SEED]}")
seed=${2:-20261124}
mkdir -p "$dir"
cargo build --release -p snooker-fuzz
git rev-parse HEAD > "$dir/commit"
for i in $(seq 0 19); do
  [ -f "$dir/part-$i.done" ] && continue
  "${CARGO_TARGET_DIR:-target}/release/snooker-fuzz" --seed "$seed" --from $((i * 50000)) --scenes 50000 \
    --out "$dir/failures-$i.toml" > "$dir/part-$i.log" 2> "$dir/part-$i.err" || true
  echo done > "$dir/part-$i.done"
done
