#!/usr/bin/env bash
# Rewrites the golden images of the rendering regression tests (data/golden/*.png) from the
# current code: run it after an intended change to the UI, the 3D view, the DRRs or the phantom,
# look at the new images (git diff shows which changed), and commit them with the change.
#   bash scripts/refresh_goldens.sh          # uses build/ (FM_BUILD_DIR to override)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${FM_BUILD_DIR:-build}
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
    cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$BUILD_DIR" --target fm_test_app -j "$(nproc)"
FM_UPDATE_GOLDENS=1 "$BUILD_DIR/tests/fm_test_app" --gtest_filter='GoldenUi.*:GoldenSliceUi.*:GoldenWorkspace.*'
# Check: the fresh goldens must now pass as they are.
"$BUILD_DIR/tests/fm_test_app" --gtest_filter='GoldenUi.*:GoldenSliceUi.*:GoldenWorkspace.*' --gtest_brief=1
git status --short data/golden 2>/dev/null || true
