#!/usr/bin/env bash
# `model-info` on the command line (own files; the JTML femur too when the shared data is there):
#  1. a closed OBJ cube (quads, inside out) reports 12 triangles, 8 vertices, closed, reversed
#     winding, volume 8;
#  2. the same cube with one face missing is reported open with its 4 boundary edges (exit 0);
#  3. a truncated binary STL exits 1 with a message naming the file.
set -uo pipefail
FM=$1
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# Faces clockwise seen from outside: the reader must flip it.
cat > "$OUT/cube.obj" <<'OBJ'
v 0 0 0
v 2 0 0
v 2 2 0
v 0 2 0
v 0 0 2
v 2 0 2
v 2 2 2
v 0 2 2
f 1 2 3 4
f 5 8 7 6
f 1 5 6 2
f 2 6 7 3
f 3 7 8 4
f 4 8 5 1
OBJ
out=$("$FM" model-info "$OUT/cube.obj") || fail "model-info cube.obj exited $?"
grep -q "12 after welding" <<<"$out" || fail "triangle count: $out"
grep -q "8 welded" <<<"$out" || fail "vertex count: $out"
grep -q "^closed       yes" <<<"$out" || fail "not closed: $out"
grep -q "reversed to outward" <<<"$out" || fail "inward winding not reported: $out"
grep -q "^volume       8 mm" <<<"$out" || fail "volume: $out"

head -n 13 "$OUT/cube.obj" > "$OUT/open.obj"
out=$("$FM" model-info "$OUT/open.obj") || fail "model-info open.obj exited $?"
grep -q "NO: silhouettes only (4 boundary edges" <<<"$out" || fail "open surface not reported: $out"

# A binary STL header claiming 5 facets, with only 2 in the file.
python3 - "$OUT/short.stl" <<'PY'
import struct, sys
open(sys.argv[1], "wb").write(b"\0" * 80 + struct.pack("<I", 5) + b"\0" * 100)
PY
msg=$("$FM" model-info "$OUT/short.stl" 2>&1) && fail "truncated STL accepted"
grep -q "short.stl" <<<"$msg" || fail "message does not name the file: $msg"
grep -q "84 + 50 \* 5 = 334" <<<"$msg" || fail "message does not give the expected size: $msg"

DATA=${FM_DATA_DIR:-$(dirname "$0")/../../../shared/data}
FEM="$DATA/jtml-kneel-tka-fluoro/KR_right_7_fem.stl"
if [ -f "$FEM" ]; then
    out=$("$FM" model-info "$FEM") || fail "model-info femur exited $?"
    grep -q "12412 in the file, 12412 after welding" <<<"$out" || fail "femur triangles: $out"
    grep -q "6208 welded" <<<"$out" || fail "femur vertices: $out"
    grep -q "^closed       yes" <<<"$out" || fail "femur not closed: $out"
fi
echo "model-info CLI checks passed"
