#!/usr/bin/env bash
# `register --camera --model` on the JTML knee (shared data; skips without it):
#  1. the femoral component of frame 0160 from a start 2-3 mm, 10 mm deep and 4 deg off the
#     fem.jts pose: the printed IoU against the label mask is at least 0.95, the written .jts
#     row is within 1 mm (x, y) and 2 deg of fem.jts, the .tra holds one 4x4 per frame row;
#  2. both implants at once from fem.jts / tib.jts, written to one .tra (two objects), side by
#     side on 2 threads with the same bytes as one after the other on 1;
#  3. bad input exits non-zero naming the file and the field, before any search: a .jts row
#     with five numbers, a singular calibration, a mask of another size, an open mesh, an
#     --out that is neither .jts nor .tra, a --frame the file does not have.
set -uo pipefail
source "$(dirname "$0")/jtml_test_prelude.sh" "$1"
IMG="$D/AT_K1_V1_0160.tif"
MASK="$D/Labels/fem/AT_K1_V1_0160_label_fem.tif"

out=$("$FM" register --reference "$IMG" --camera "$CAL" --model "$FEM" --invert \
    --start 20,18,-1017,-24,-5,2 --mask "$MASK" --out "$OUT/fem.jts" --threads 2) ||
    fail "register exited $?: $out"
grep -q "^final pose" <<<"$out" || fail "no final pose: $out"
grep -q "^similarity" <<<"$out" || fail "no similarity: $out"
grep -q "^time" <<<"$out" || fail "no time: $out"
# How sure: two searches from independent starts agree, the mask and the outline confirm it; the
# spread per coordinate, depth the weak one of one view.
grep -q "^verdict     ok: 2 of 2 searches from different starts end here; silhouette IoU" <<<"$out" ||
    fail "no ok verdict with its reasons: $out"
grep -q "^uncertainty u .* mm, v .* mm, depth .* mm, about u .* deg" <<<"$out" || fail "no uncertainty line: $out"
grep -q "^run 2 " <<<"$out" || fail "no second search: $out"
iou=$(sed -n 's/^IoU *\([0-9.]*\) .*/\1/p' <<<"$out")
python3 -c "import sys; sys.exit(0 if float('$iou') >= 0.95 else 1)" || fail "IoU $iou < 0.95"
python3 - "$OUT/fem.jts" "$D/fem.jts" <<'PY' || fail "written pose is not near fem.jts"
import sys
def row(p):
    lines = open(p).read().split("\n")
    assert lines[0].strip() == "JT_EULER_312", lines[0]
    return [float(x) for x in lines[2].split(",")]
a, b = row(sys.argv[1]), row(sys.argv[2])
assert abs(a[0] - b[0]) < 1 and abs(a[1] - b[1]) < 1, (a, b)
assert all(abs(a[i] - b[i]) < 2 for i in (3, 4, 5)), (a, b)
PY

out=$("$FM" register --reference "$D/AT_K1_V1_0170.tif" --camera "$CAL" --model "$FEM" --model "$TIB" \
    --invert --start "$D/fem.jts" --start "$D/tib.jts" --frame 1 --out "$OUT/both.tra" --threads 2) ||
    fail "two-model register exited $?: $out"
grep -q "^total time" <<<"$out" || fail "no total time: $out"
[ "$(grep -c "^verdict     ok" <<<"$out")" = 2 ] || fail "both implants' verdicts must be ok: $out"
python3 - "$OUT/both.tra" <<'PY' || fail "both.tra layout"
import sys
rows = [l for l in open(sys.argv[1]).read().split("\n") if l]
assert len(rows) == 2, rows
assert all(v == "NaN" for v in rows[0].split(",")) and len(rows[0].split(",")) == 32
vals = [float(v) for v in rows[1].split(",")]
assert len(vals) == 32 and vals[12:16] == [0, 0, 0, 1] and vals[28:32] == [0, 0, 0, 1], vals
PY
# The two models ran side by side (one per core); one thread runs them one after the other:
# the same answers to the last digit.
grep -q "side by side" <<<"$out" || fail "two models on 2 threads not side by side: $out"
out1=$("$FM" register --reference "$D/AT_K1_V1_0170.tif" --camera "$CAL" --model "$FEM" --model "$TIB" \
    --invert --start "$D/fem.jts" --start "$D/tib.jts" --frame 1 --out "$OUT/both1.tra" --threads 1) ||
    fail "two-model register, 1 thread, exited $?: $out1"
grep -q "one after the other" <<<"$out1" || fail "1 thread not one after the other: $out1"
cmp -s "$OUT/both.tra" "$OUT/both1.tra" || fail "side by side and one after the other differ:
$(cat "$OUT/both.tra")
$(cat "$OUT/both1.tra")"

# The same file name twice (here the same STL through two paths) is two models: each is
# registered on its own and both land where one alone does (the second used to move the first,
# hidden one, and end 17 mm off).
mkdir -p "$OUT/a" "$OUT/b"; ln -s "$(realpath "$FEM")" "$OUT/a/implant.stl"; ln -s "$(realpath "$FEM")" "$OUT/b/implant.stl"
out=$("$FM" register --reference "$D/AT_K1_V1_0170.tif" --camera "$CAL" --model "$OUT/a/implant.stl" \
    --model "$OUT/b/implant.stl" --invert --start "$D/fem.jts" --start "$D/fem.jts" --frame 1 \
    --out "$OUT/twice.tra" --threads 2) || fail "the same model twice exited $?: $out"
python3 - "$OUT/twice.tra" "$OUT/both.tra" <<'PY' || fail "two models of one file name differ from one alone"
import sys
twice = [float(v) for v in open(sys.argv[1]).read().split("\n")[1].split(",")]
alone = [float(v) for v in open(sys.argv[2]).read().split("\n")[1].split(",")][:16]
assert twice[:16] == twice[16:], (twice[:16], twice[16:])
assert twice[:16] == alone, (twice[:16], alone)
PY

REFUSED_BEFORE="^final pose"
source "$(dirname "$0")/cli_refuse.sh"
base=(--reference "$IMG" --camera "$CAL" --model "$FEM" --invert)
printf 'JT_EULER_312\nx,y,z,zr,xr,yr\n1,2,3,4,5\n' > "$OUT/five.jts"
refuse "a .jts row with five numbers" "five.jts: line 3" "${base[@]}" --start "$OUT/five.jts"
printf 'JT_INTCALIB\n1198\n0\n0\n0\n' > "$OUT/singular.txt"
refuse "a zero pixel pitch" "singular.txt" --reference "$IMG" --camera "$OUT/singular.txt" \
    --model "$FEM" --start "$D/fem.jts"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\n' > "$OUT/open.obj"
refuse "an open mesh" "open.obj" --reference "$IMG" --camera "$CAL" --model "$OUT/open.obj" \
    --start "$D/fem.jts"
refuse "--out .txt" "must end in .jts or .tra" "${base[@]}" --start "$D/fem.jts" --out "$OUT/p.txt"
refuse "a frame the file does not have" "frame 5 does not exist" "${base[@]}" --start "$D/fem.jts" --frame 5
refuse "two starts for one model" "one per --model" "${base[@]}" --start "$D/fem.jts" --start "$D/tib.jts"
refuse "a mask per model" "--mask" "${base[@]}" --start "$D/fem.jts" --mask "$MASK" --mask "$MASK"
refuse "--max-runs below --runs" "must be at least --runs" "${base[@]}" --start "$D/fem.jts" --runs 3 --max-runs 2
refuse "--runs 0" "--runs" "${base[@]}" --start "$D/fem.jts" --runs 0
# A mask of another size: a 16 x 16 PNG (stb reads it), written with python's zlib.
python3 - "$OUT/small.png" <<'PY'
import struct, sys, zlib
w = h = 16
raw = b"".join(b"\0" + bytes(w) for _ in range(h))
def chunk(t, d): return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
open(sys.argv[1], "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0))
    + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
PY
refuse "a mask of another size" "small.png" "${base[@]}" --start "$D/fem.jts" --mask "$OUT/small.png"
# Blind starts: nothing of the model on valid pixels. Refused with the numbers, never a "final pose".
refuse "a start behind the source" "behind the source" "${base[@]}" --start 0,0,1000,0,0,0
refuse "a start 100 m away" "valid pixels" "${base[@]}" --start 0,0,-100000,0,0,0
refuse "an ROI away from the model" "check --roi" "${base[@]}" --start "$D/fem.jts" --roi 0,0,40,40
python3 - "$FEM" "$OUT/metres.stl" <<'PY'
import sys  # the ASCII STL's vertices in metres
out = []
for line in open(sys.argv[1]):
    w = line.split()
    out.append("vertex " + " ".join(repr(float(x) / 1000) for x in w[1:4]) + "\n" if w and w[0] == "vertex" else line)
open(sys.argv[2], "w").writelines(out)
PY
refuse "a mesh in metres" "in metres" --reference "$IMG" --camera "$CAL" --model "$OUT/metres.stl" --invert --start "$D/fem.jts"
refuse "--camera without --model" "needs --model" --reference "$IMG" --camera "$CAL" --start "$D/fem.jts"
echo "register --camera --model CLI checks passed"
