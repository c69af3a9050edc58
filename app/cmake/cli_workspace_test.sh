#!/usr/bin/env bash
# The app's real X-ray workspace from the command line (shared data; skips without it):
#  1. `screenshot --trial` on the shipped JTML and wrist trials writes a 1280 x 800 PNG, the
#     same bytes twice; `screenshot --reference --camera --model --start` too;
#  2. `app --trial` without a display falls back to the headless screenshot, exit 0;
#  3. bad input exits non-zero naming the file or the option, before any window: a calibration
#     that fails, a radiograph of another size than its calibration, an open mesh, --reference
#     without --camera, preparation flags with --trial, a --frame the trial does not have.
set -uo pipefail
FM=$1
REPO=$(cd "$(dirname "$0")/../.." && pwd)
DATA=${FM_DATA_DIR:-$REPO/../shared/data}
D="$DATA/jtml-kneel-tka-fluoro"
# Under CI=true missing data is a failure, never a skip.
skip() { [ "${CI:-}" = "true" ] && { echo "FAIL under CI: $1"; exit 1; }; echo "$1: skipped"; exit 77; }
[ -f "$D/fem.jts" ] || skip "shared data not found"
[ "$(cd "$DATA" && pwd -P)" = "$(cd "$REPO/../shared/data" 2>/dev/null && pwd -P)" ] ||
    skip "the shipped trials name ../shared/data beside the repository"
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
TRIAL="$REPO/data/trials/jtml-knee.json"

"$FM" screenshot --trial "$TRIAL" --out "$OUT/a.png" --threads 2 >/dev/null || fail "screenshot --trial exited $?"
"$FM" screenshot --trial "$TRIAL" --out "$OUT/b.png" --threads 2 >/dev/null || fail "second screenshot exited $?"
cmp -s "$OUT/a.png" "$OUT/b.png" || fail "two screenshots of the trial differ"
# The radiograph flags over the trial's preparation reach the workspace: log-prepared frames look otherwise.
"$FM" screenshot --trial "$TRIAL" --log --out "$OUT/log.png" --threads 2 >/dev/null || fail "screenshot --trial --log exited $?"
cmp -s "$OUT/a.png" "$OUT/log.png" && fail "--log did not change the trial's prepared frames"
python3 - "$OUT/a.png" <<'PY' || fail "not a 1280 x 800 PNG"
import struct, sys
d = open(sys.argv[1], "rb").read(24)
assert d[:8] == b"\x89PNG\r\n\x1a\n" and struct.unpack(">II", d[16:24]) == (1280, 800)
PY
if [ -d "$DATA/autoscoper-bvr" ]; then
    "$FM" screenshot --trial "$REPO/data/trials/wrist.json" --frame 1 --side-by-side --out "$OUT/w.png" \
        --threads 2 >/dev/null || fail "screenshot of the wrist trial exited $?"
fi
"$FM" screenshot --reference "$D/AT_K1_V1_0170.tif" --camera "$D/calibration.txt" --model "$D/KR_right_7_fem.stl" \
    --start "$D/fem.jts" --frame 1 --invert --drr --out "$OUT/r.png" --threads 2 >/dev/null ||
    fail "screenshot --reference exited $?"
out=$(DISPLAY= WAYLAND_DISPLAY= "$FM" app --trial "$TRIAL" --headless-out "$OUT/h.png" --threads 2 2>&1) ||
    fail "app --trial without a display exited $?: $out"
[ -s "$OUT/h.png" ] || fail "no fallback screenshot: $out"

expect_error() {  # expect_error WHAT NEEDLE ARGS...
    local what=$1 needle=$2
    shift 2
    local msg
    if msg=$("$FM" "$@" 2>&1); then fail "$what: exited 0"; fi
    grep -qF -- "$needle" <<<"$msg" || fail "$what: message does not name $needle: $msg"
}
printf 'JT_INTCALIB\n1198\n0\n0\n0\n' >"$OUT/bad_calib.txt"
expect_error "bad calibration" bad_calib.txt screenshot --reference "$D/AT_K1_V1_0160.tif" \
    --camera "$OUT/bad_calib.txt" --model "$D/KR_right_7_fem.stl" --out "$OUT/x.png"
if [ -d "$DATA/autoscoper-bvr" ]; then
    expect_error "image size" 1760 app --reference "$D/AT_K1_V1_0160.tif" \
        --camera "$DATA/autoscoper-bvr/Calibration/xr_calib_wrist_cam01.txt" --model "$D/KR_right_7_fem.stl"
fi
printf 'solid o\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid o\n' \
    >"$OUT/open.stl"
expect_error "open mesh" open.stl app --reference "$D/AT_K1_V1_0160.tif" --camera "$D/calibration.txt" \
    --model "$OUT/open.stl"
expect_error "no camera" "--camera" app --reference "$D/AT_K1_V1_0160.tif" --model "$D/KR_right_7_fem.stl"
expect_error "flags with a trial: both values" "--invert with --log" app --trial "$TRIAL" --invert --log
expect_error "frame out of range" "--frame 5" app --trial "$TRIAL" --frame 5
# A file the user gave is named by its option, not as part of a one-camera "trial 'X.tif'".
for args in "--camera $OUT/missing.txt --model $D/KR_right_7_fem.stl|--camera: file not found: '$OUT/missing.txt'" \
            "--camera $D/calibration.txt --model $OUT|--model: '$OUT' is a folder" \
            "--camera $D/calibration.txt --model $D/KR_right_7_fem.stl --mask $OUT/none.png|--mask: file not found"; do
    expect_error "a missing file" "${args#*|}" screenshot --reference "$D/AT_K1_V1_0160.tif" ${args%%|*} --out "$OUT/x.png"
    if msg=$("$FM" screenshot --reference "$D/AT_K1_V1_0160.tif" ${args%%|*} --out "$OUT/x.png" 2>&1); then :; fi
    grep -q "trial '\|cam1" <<<"$msg" && fail "the message speaks of a trial the user did not give: $msg"
done
echo "cli_workspace_test: all checks passed"
