#!/usr/bin/env bash
# Camera calibrations on the command line (needs the shared data; skips without it):
#  1. `geometry --camera` prints a MayaCam 2.0 calibration as geometry JSON whose source is the
#     camera centre; `--out cam.txt` writes MayaCam 2.0 that reads back to the same JSON;
#  2. a JointTrack calibration without --image-size is refused (exit 1), with it accepted;
#  3. a calibration that disagrees with --image-size is refused;
#  4. `radiograph` writes the prepared image and its mask at the frame's size, and refuses an
#     roi outside the image and a calibration of another size.
set -uo pipefail
FM=$1
. "$(dirname "$0")/require_shared_data.sh"
require_shared_data autoscoper-bvr/Calibration/xr_calib_wrist_cam01.txt jtml-kneel-tka-fluoro/calibration.txt
CAM="$DATA/autoscoper-bvr/Calibration/xr_calib_wrist_cam01.txt"
JT="$DATA/jtml-kneel-tka-fluoro/calibration.txt"
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$FM" geometry --camera "$CAM" > "$OUT/a.json" || fail "geometry --camera exited $?"
python3 - "$OUT/a.json" <<'PY' || fail "source is not the camera centre (-530.0, 87.9, -728.2)"
import json, sys
s = json.load(open(sys.argv[1]))["source"]
assert all(abs(a - b) < 0.1 for a, b in zip(s, (-530.0, 87.9, -728.2))), s
PY
"$FM" geometry --camera "$CAM" --out "$OUT/cam.txt" || fail "--out cam.txt exited $?"
[ "$(head -1 "$OUT/cam.txt")" = "image size" ] || fail "cam.txt is not MayaCam 2.0"
"$FM" geometry --camera "$OUT/cam.txt" > "$OUT/b.json" || fail "reading the written cam.txt exited $?"
python3 - "$OUT/a.json" "$OUT/b.json" <<'PY' || fail "MayaCam 2.0 written and read back gives another geometry"
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
flat = lambda g: g["source"] + sum((g["detector"][k] for k in ("size", "spacing", "origin", "u", "v")), [])
assert all(abs(x - y) < 1e-9 for x, y in zip(flat(a), flat(b))), (a, b)
PY

"$FM" geometry --camera "$JT" > /dev/null 2>&1 && fail "JointTrack calibration without --image-size accepted"
"$FM" geometry --camera "$JT" --image-size 1024x1024 > /dev/null || fail "JointTrack with --image-size exited $?"
msg=$("$FM" geometry --camera "$CAM" --image-size 1024x1024 2>&1) && fail "size mismatch accepted"
grep -q "image size" <<<"$msg" || fail "size mismatch message does not name the field: $msg"
FRAME="$DATA/jtml-kneel-tka-fluoro/AT_K1_V1_0160.tif"
png_size() { python3 -c "import struct,sys; d=open(sys.argv[1],'rb').read(24); \
assert d[:8]==b'\x89PNG\r\n\x1a\n'; print('%dx%d' % struct.unpack('>II', d[16:24]))" "$1"; }
msg=$("$FM" radiograph "$FRAME" --invert --exclude-below 0 --roi 10,20,1000,900 --camera "$JT" \
      --out "$OUT/p.png" --mask-out "$OUT/m.png" 2>&1) || fail "radiograph exited $?: $msg"
grep -q "size         1024 x 1024" <<<"$msg" || fail "radiograph did not print the size: $msg"
grep -q "valid " <<<"$msg" || fail "radiograph did not print the valid pixel count: $msg"
[ "$(png_size "$OUT/p.png")" = "1024x1024" ] || fail "prepared PNG is not 1024x1024"
[ "$(png_size "$OUT/m.png")" = "1024x1024" ] || fail "mask PNG is not 1024x1024"
"$FM" radiograph "$FRAME" --roi 900,900,200,200 > /dev/null 2>&1 && fail "roi outside the image accepted"
"$FM" radiograph "$FRAME" --camera "$CAM" > /dev/null 2>&1 && fail "1760x1760 calibration accepted for a 1024x1024 frame"
# JointTrack without a size names the option that gives it; a model given as the calibration is
# named as one (it was "too large for a camera calibration").
msg=$("$FM" geometry --camera "$JT" 2>&1) && fail "JointTrack without --image-size accepted"
grep -q -- "--image-size WxH" <<<"$msg" || fail "JointTrack without a size does not name --image-size: $msg"
msg=$("$FM" geometry --camera "$DATA/jtml-kneel-tka-fluoro/KR_right_7_fem.stl" 2>&1) && fail "an STL accepted as a calibration"
grep -q "is a model (.stl), not a camera calibration" <<<"$msg" || fail "an STL as calibration: $msg"
echo "camera CLI checks passed"
