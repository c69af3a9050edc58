#!/usr/bin/env bash
# Screenshots for the README and docs, made by the app itself headless (OSMesa, no display):
# docs/images/*.png. Deterministic: the same build gives the same pixels.
#   bash scripts/make_screenshots.sh         # uses build/ (FM_BUILD_DIR to override)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${FM_BUILD_DIR:-build}
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
    cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$BUILD_DIR" --target fluoromatch -j "$(nproc)"
FM="$BUILD_DIR/app/fluoromatch"
OUT=docs/images
mkdir -p "$OUT"
REF="-10,5,10,30,15,-10"   # a line of data/reference_poses.txt: oblique from above
"$FM" screenshot --out "$OUT/app.png" --reference-pose "$REF" --pose 0,0,0,20,0,0
"$FM" screenshot --out "$OUT/app-match-hints.png" --reference-pose "$REF" \
    --pose -4,5,10,38,10,-10 --match --compare overlay
"$FM" screenshot --out "$OUT/app-matched.png" --reference-pose "$REF" --pose "$REF" --match \
    --compare difference --view -35,20,1.4
"$FM" screenshot --out "$OUT/app-help.png" --reference-pose "$REF" --help-window
ls -l "$OUT"
