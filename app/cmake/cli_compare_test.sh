#!/usr/bin/env bash
# `fluoromatch compare` against numbers computed here from the files (shared data; skips without):
#  1. the JTML fem.jts against itself: every error 0, every frame within tolerance;
#  2. fem.jts against a registration of frame 0160 only: frames 1 and 2 named as missing in the
#     result, frame 0's centre error and rotation angle equal to those computed from the two
#     rows here (JT_EULER_312: R = Rz Rx Ry; the centre is --center in the model's frame);
#     the CSV's rows and the PNG plot written;
#  3. a trial's .tra against a copy with one frame moved 0.7 mm: that frame's centre error 0.7,
#     camera columns present (camera 1 of the trial);
#  4. refusals: --camera or --center with --trial, --bone without --trial, a multi-object .tra
#     without --trial, a plot that is not .png, no frame in common.
set -uo pipefail
FM=$1
SRC=$(cd "$(dirname "$0")/../.." && pwd)
. "$(dirname "$0")/require_shared_data.sh"
require_shared_data jtml-kneel-tka-fluoro/fem.jts autoscoper-bvr
D="$DATA/jtml-kneel-tka-fluoro"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
field() { sed -n "s/^  $1 *\([-0-9.]*\) *\([-0-9.]*\) *\([-0-9.]*\) *\([-0-9.]*\)$/\\$2/p" <<<"$3"; }

out=$("$FM" compare --truth "$D/fem.jts" --tra "$D/fem.jts") || fail "self compare exited $?: $out"
grep -q "^compared  3 frames" <<<"$out" || fail "3 frames: $out"
grep -q "1 mm and 2 deg: 100.0 % (3 of 3); 0.5 mm and 0.5 deg: 100.0 % (3 of 3)" <<<"$out" || fail "within: $out"
[ "$(field centre 4 "$out")" = "0.0000" ] && [ "$(field rotation 4 "$out")" = "0.0000" ] || fail "not zero: $out"
grep -q "cam x mm" <<<"$out" || fail ".jts files have the JointTrack camera frame: $out"

"$FM" register --reference "$D/AT_K1_V1_0160.tif" --camera "$D/calibration.txt" --model "$D/KR_right_7_fem.stl" \
    --invert --start 20,18,-1017,-24,-5,2 --out "$T/fem0.jts" --threads 2 >/dev/null || fail "register failed"
out=$("$FM" compare --truth "$D/fem.jts" --tra "$T/fem0.jts" --center 5,-10,20 --csv "$T/c.csv" --plot "$T/c.png") ||
    fail "compare exited $?: $out"
grep -q "^compared  1 frames" <<<"$out" || fail "1 frame compared: $out"
grep -q "^missing   in the result: 2 (frames 1, 2)" <<<"$out" || fail "missing frames not named: $out"
centre=$(field centre 4 "$out")
rotation=$(field rotation 4 "$out")
python3 - "$D/fem.jts" "$T/fem0.jts" "$centre" "$rotation" <<'PY' || fail "frame 0's errors differ from the arithmetic: $out"
import math, sys
def row(path):
    return [float(x) for x in open(path).read().split("\n")[2].split(",")]
def rot(zr, xr, yr):  # JT_EULER_312: R = Rz(z) Rx(x) Ry(y)
    c, s = math.cos, math.sin
    z, x, y = map(math.radians, (zr, xr, yr))
    Rz = [[c(z), -s(z), 0], [s(z), c(z), 0], [0, 0, 1]]
    Rx = [[1, 0, 0], [0, c(x), -s(x)], [0, s(x), c(x)]]
    Ry = [[c(y), 0, s(y)], [0, 1, 0], [-s(y), 0, c(y)]]
    mul = lambda a, b: [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return mul(mul(Rz, Rx), Ry)
t, r = row(sys.argv[1]), row(sys.argv[2])
Rt, Rr = rot(*t[3:]), rot(*r[3:])
c = [5, -10, 20]
pt = [sum(Rt[i][k] * c[k] for k in range(3)) + t[i] for i in range(3)]
pr = [sum(Rr[i][k] * c[k] for k in range(3)) + r[i] for i in range(3)]
centre = math.dist(pt, pr)
trace = sum(sum(Rr[i][k] * Rt[i][k] for k in range(3)) for i in range(3))  # trace(Rr Rt^T)
angle = math.degrees(math.acos(max(-1, min(1, (trace - 1) / 2))))
assert abs(centre - float(sys.argv[3])) < 1e-4 and abs(angle - float(sys.argv[4])) < 1e-4, (centre, angle, sys.argv)
assert 0 < centre < 2 and angle < 3, (centre, angle)
PY
[ "$(wc -l < "$T/c.csv")" -eq 4 ] || fail "CSV: a header and 3 rows: $(cat "$T/c.csv")"
grep -q "^1,missing in the result" "$T/c.csv" && grep -q "^0,compared," "$T/c.csv" || fail "CSV rows: $(cat "$T/c.csv")"
[ "$(head -c 8 "$T/c.png" | od -An -c | tr -d ' ')" = "211PNG\r\n032\n" ] || fail "the plot is not a PNG"

TRIAL=$SRC/data/trials/wrist.json
"$FM" track --trial "$TRIAL" --bone radius --frames 0:2 --threads 2 --out "$T/r.tra" >/dev/null 2>&1 || fail "track failed"
python3 - "$T/r.tra" "$T/moved.tra" <<'PY'
import sys
rows = open(sys.argv[1]).read().split("\n")
v = rows[1].split(",")
v[3] = "%.16f" % (float(v[3]) + 0.7)  # frame 1 moved 0.7 mm along the world x
rows[1] = ",".join(v)
open(sys.argv[2], "w").write("\n".join(rows))
PY
out=$("$FM" compare --truth "$T/r.tra" --tra "$T/moved.tra" --trial "$TRIAL" --bone radius --csv "$T/r.csv") ||
    fail "trial compare exited $?: $out"
grep -q "^camera    camera 1 of" <<<"$out" && grep -q "cam x mm" <<<"$out" || fail "camera columns: $out"
[ "$(field centre 4 "$out")" = "0.7000" ] && [ "$(field rotation 4 "$out")" = "0.0000" ] || fail "0.7 mm: $out"
grep -q "^1,compared,0.700000,0.000000" "$T/r.csv" || fail "frame 1's row: $(cat "$T/r.csv")"

expect_error() {  # expect_error TEXT args...
    local text=$1; shift
    if "$FM" compare "$@" >"$T/out" 2>&1; then fail "'compare $*' succeeded"; fi
    grep -q -- "$text" "$T/out" || { cat "$T/out"; fail "'compare $*' did not say '$text'"; }
}
expect_error "--camera applies without --trial" --truth "$T/r.tra" --tra "$T/r.tra" --trial "$TRIAL" --bone radius --camera "$D/calibration.txt"
expect_error "--center applies without --trial" --truth "$T/r.tra" --tra "$T/r.tra" --trial "$TRIAL" --bone radius --center 1,2,3
expect_error "--bone needs --trial" --truth "$T/r.tra" --tra "$T/r.tra" --bone radius
expect_error "name it NAME.png" --truth "$T/r.tra" --tra "$T/r.tra" --plot "$T/p.jpg"
printf 'NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN\n' > "$T/none.tra"
expect_error "no frame holds a pose in both" --truth "$T/r.tra" --tra "$T/none.tra"
expect_error "give an Autoscoper .tra or a JointTrack .jts" --truth "$T/r.csv" --tra "$T/r.tra"
echo "compare: ok"
