#!/usr/bin/env bash
# Regenerates docs/img/break-off.png: the break-off recording as the Rerun viewer shows it by
# default (the layout shipped in the recording), rendered without a display.
#
# Installs what it needs itself: software Vulkan (Mesa) through apt, and the viewer
# (rerun-sdk, the version the recordings are written with) in a venv under target/.
# Usage: scripts/screenshot.sh [OUT.png [RECORDING.rrd]]   (default docs/img/break-off.png of
# the break-off; with a recording, e.g. a discrepancy report's overlay.rrd, that one instead)
set -euo pipefail
cd "$(dirname "$0")/.."

RERUN_VERSION=0.36.3
OUT=${1:-docs/img/break-off.png}
VENV=target/rerun-venv
RRD=${2:-target/screenshot/break-off.rrd}

if ! dpkg -s mesa-vulkan-drivers libvulkan1 >/dev/null 2>&1; then
    SUDO=$([ "$(id -u)" -eq 0 ] || echo sudo)
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq --no-install-recommends mesa-vulkan-drivers libvulkan1
fi
if ! "$VENV/bin/rerun" --version 2>/dev/null | grep -q "$RERUN_VERSION"; then
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install --quiet "rerun-sdk==$RERUN_VERSION"
fi

mkdir -p "$(dirname "$OUT")"
if [ $# -lt 2 ]; then
    cargo build --release --quiet --bin snooker
    mkdir -p "$(dirname "$RRD")"
    target/release/snooker simulate --quiet --record "$RRD"
fi

# A fresh home so that no layout or setting saved by an earlier viewer session is used (and
# analytics stay off); `--port auto` starts a new viewer even if one listens on 9876;
# RUST_LOG=error keeps start-up notices (software renderer, server address) off the picture.
VIEWER_HOME=$(mktemp -d)
trap 'rm -rf "$VIEWER_HOME"' EXIT
viewer() {
    HOME=$VIEWER_HOME XDG_CONFIG_HOME=$VIEWER_HOME/config XDG_DATA_HOME=$VIEWER_HOME/data \
        XDG_CACHE_HOME=$VIEWER_HOME/cache RUST_LOG=error "$VENV/bin/rerun" "$@"
}
viewer analytics disable >/dev/null 2>&1
viewer "$RRD" --headless --port auto --window-size 1200x750 --screenshot-to "$OUT"
# The viewer renders at twice the window size; halve it to keep the file small (Pillow comes
# with rerun-sdk).
"$VENV/bin/python" - "$OUT" <<'PY'
import sys
from PIL import Image
path = sys.argv[1]
image = Image.open(path).convert("RGB")
image.resize((image.width // 2, image.height // 2), Image.LANCZOS).save(path, optimize=True)
PY
echo "wrote $OUT"
