#!/usr/bin/env bash
# `fluoromatch track` on the shipped wrist trial: refusals name what is wrong; the .tra is one
# row per trial frame (16 numbers, NaN where not tracked); a run killed after a frame and
# resumed gives the same file, byte for byte, as one uninterrupted run.
set -euo pipefail
FM=$1
SRC=$(cd "$(dirname "$0")/../.." && pwd)
TRIAL=$SRC/data/trials/wrist.json
if [ ! -d "$SRC/../shared/data/autoscoper-bvr" ]; then
    if [ "${CI:-}" = "true" ]; then echo "FAIL: ../shared/data/autoscoper-bvr missing under CI"; exit 1; fi
    echo "SKIP: ../shared/data/autoscoper-bvr not found beside the repository"; exit 77
fi
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
expect_error() {  # expect_error TEXT command...
    local text=$1; shift
    if "$@" >"$T/out" 2>&1; then fail "'$*' succeeded"; fi
    grep -q -- "$text" "$T/out" || { cat "$T/out"; fail "'$*' did not say '$text'"; }
}
expect_error "radius, ulna, mc3" "$FM" track --trial "$TRIAL" --bone femur --out "$T/x.tra"
expect_error "frames 0..2" "$FM" track --trial "$TRIAL" --bone radius --frames 0:5 --out "$T/x.tra"
expect_error "no frame of radius could be tracked" "$FM" track --trial "$TRIAL" --bone radius --frames 0:0 --out "$T/x.tra"
printf 'Version 1.1\nmayaCam_csv nothere.txt\nCameraRootDir .\nVolumeFile v.tif\nVoxelSize 1 1 1\n' > "$T/bad.cfg"
expect_error "nothere.txt" "$FM" track --trial "$T/bad.cfg" --bone v --out "$T/x.tra"

# A start pose at frame 0 (Autoscoper's volume frame at the calibration origin: in camera 1's view).
{ echo "1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1"; for i in 1 2; do
    echo "NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN"; done; } > "$T/start.tra"
"$FM" track --trial "$TRIAL" --bone radius --start "$T/start.tra" --frames 0:1 --threads 2 \
    --out "$T/whole.tra" --csv "$T/whole.csv" >/dev/null 2>&1 || fail "uninterrupted run failed"
[ "$(wc -l < "$T/whole.tra")" -eq 3 ] || fail "the .tra must have one row per trial frame"
awk -F, 'NR<=2 && (NF!=16 || $16+0!=1) {exit 1} NR==3 && $1!="NaN" {exit 1}' "$T/whole.tra" \
    || fail "rows must be 16 numbers (last 1), NaN where not tracked"
head -1 "$T/whole.csv" | grep -q "cost_cam1,cost_cam2,evaluations,time_ms" || fail "CSV header"
# "Killed" after frame 0, then resumed.
"$FM" track --trial "$TRIAL" --bone radius --start "$T/start.tra" --frames 0:0 --threads 2 \
    --out "$T/resumed.tra" >/dev/null 2>&1 || fail "first part failed"
"$FM" track --trial "$TRIAL" --bone radius --start "$T/start.tra" --frames 0:1 --threads 2 --resume \
    --out "$T/resumed.tra" >"$T/out" 2>&1 || { cat "$T/out"; fail "resume failed"; }
grep -q "1 frames of radius already in" "$T/out" || fail "resume did not say what it kept"
cmp "$T/whole.tra" "$T/resumed.tra" || fail "resumed run differs from the uninterrupted one"
echo "track CLI: all checks passed"
