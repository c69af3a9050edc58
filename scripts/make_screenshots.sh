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
# Views that need the real data beside the repository (skipped without it).
DATA=${FM_DATA_DIR:-../shared/data}
if [ -d "$DATA/jtml-kneel-tka-fluoro" ] && [ -d "$DATA/mricron-ch2" ]; then
    J=$DATA/jtml-kneel-tka-fluoro
    # One raw radiograph opened without --invert: the workspace says it looks raw.
    "$FM" screenshot --out "$OUT/workspace-raw-hint.png" --reference "$J/AT_K1_V1_0160.tif" \
        --camera "$J/calibration.txt" --model "$J/KR_right_7_fem.stl" --start "$J/fem.jts"
    # The MRI slice mode on ch2: the 3D view's head drawn from 5^3 block means.
    "$FM" screenshot --out "$OUT/app-mri-ch2.png" --volume "$DATA/mricron-ch2/ch2.nii.gz"
else
    echo "make_screenshots: $DATA not found: the real-data views are not made"
fi
ls -l "$OUT"
