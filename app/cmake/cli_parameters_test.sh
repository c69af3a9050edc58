#!/usr/bin/env bash
# Parameters that used to be taken silently are refused, naming the option and the limit:
# --budget 0, --polish-budget -1, --seed -1 (would wrap), --start / --pose / --distance / --film
# 1e308, --component-near nan, --mode approx (removed), --size out of range, a geometry JSON with a
# duplicate key or a source at 1e308. No output file is written for any of them.
set -uo pipefail
FM=$1
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
refused() {  # expected-fragment, command...
    local fragment=$1; shift
    local msg rc
    msg=$("$@" 2>&1)
    rc=$?
    [ $rc -ne 0 ] || fail "accepted (exit 0): $*"
    grep -qF -- "$fragment" <<<"$msg" || fail "refusal of '$*' does not say '$fragment': $msg"
    [ -z "$(ls -A "$OUT" | grep -v '^g.*\.json$')" ] || fail "'$*' wrote $(ls -A "$OUT")"
}
refused "--budget: Value 0 not in range 1" "$FM" register --reference-pose 1,0,0,0,0,0 --budget 0
refused "--polish-budget: Value -1 not in range 0" "$FM" register --reference-pose 1,0,0,0,0,0 --polish-budget -1
refused "--seed: must be a whole number" "$FM" register --reference-pose 1,0,0,0,0,0 --seed -1
refused "--seed: must be a whole number" "$FM" screenshot --seed -1 --out "$OUT/s.png"
refused "--start: pose x offset 1e+308 mm is beyond" "$FM" register --reference-pose 1,0,0,0,0,0 --start 1e308,0,0,0,0,0
refused "--component-near: must be a finite number" "$FM" mesh --component-near nan 0 0 --out "$OUT/m.obj"
refused "pose x offset 1e+308 mm is beyond" "$FM" drr --pose 1e308,0,0,0,0,0 --out "$OUT/d.png"
refused "source-to-isocenter distance must be positive and at most" "$FM" drr --distance 1e308 --out "$OUT/d.png"
refused "film width must be positive and at most" "$FM" drr --film 1e308x1e308 --out "$OUT/d.png"
refused "--mode approx was removed" "$FM" drr --mode approx --out "$OUT/d.png"
refused "--voxels: int8 not in {auto,float}" "$FM" drr --voxels int8 --out "$OUT/d.png"
# One --size parser (cli/ValueChecks.h) with each command's limit.
refused '--size "10x10": expected WIDTHxHEIGHT, whole numbers of pixels 16..8192' "$FM" screenshot --size 10x10 --out "$OUT/s.png"
refused '--size "5000x64": expected WIDTHxHEIGHT, whole numbers of pixels 16..4096' "$FM" simulate --volume phantom:knee --labels phantom:knee --bone femur --motion rotate:axis=x,angle=0:5 --size 5000x64 --out "$OUT/sim"
refused '--size "64x64x2"' "$FM" screenshot --size 64x64x2 --out "$OUT/s.png"
# The box phantom holds whole numbers: stored as int16 by default, as float with --voxels float;
# in raw values both stores give the same bytes, in either walk.
for walk in dense bricks; do
    "$FM" drr --volume phantom:box --walk $walk --values raw --raw "$OUT/a.mha" 2>/dev/null | grep -q "as int16" || fail "drr on phantom:box did not store int16"
    "$FM" drr --volume phantom:box --walk $walk --voxels float --values raw --raw "$OUT/f.mha" 2>/dev/null | grep -q "as float32" || fail "drr --voxels float did not store float32"
    cmp -s "$OUT/f.mha" "$OUT/a.mha" || fail "int16 and float stores gave different raw images ($walk walk)"
    rm -f "$OUT/f.mha" "$OUT/a.mha"
done
"$FM" geometry --pose 0,0,0,0,0,0 --center 0,0,0 --out "$OUT/g.json" > /dev/null || fail "geometry exited $?"
sed 's/"source": \[/"source": [1e308, 0, 0], "source": [/' "$OUT/g.json" > "$OUT/g-dup.json"
refused "duplicate key" "$FM" drr --geometry "$OUT/g-dup.json" --out "$OUT/d.png"
sed 's/"source": \[[^]]*\]/"source": [1e308, 0, 0]/' "$OUT/g.json" > "$OUT/g-far.json"
refused '"source" must lie within' "$FM" drr --geometry "$OUT/g-far.json" --out "$OUT/d.png"
sed 's/"spacing": \[[^]]*\]/"spacing": [1e300, 1e300]/' "$OUT/g.json" > "$OUT/g-wide.json"
refused '"detector.spacing[0]" makes the film' "$FM" drr --geometry "$OUT/g-wide.json" --out "$OUT/d.png"
# Sentinels never hide a value: --i0 0 and --angles 0 are refused, not read as "not given";
# --page is bounded (2147483647 printed "page -2147483648") and applies to TIFF only.
IN=$(mktemp -d); trap 'rm -rf "$OUT" "$IN"' EXIT
"$FM" drr --size 16x16 --out "$IN/r.tif" >/dev/null 2>&1 || fail "could not write a TIFF"
"$FM" drr --size 16x16 --out "$IN/r.png" >/dev/null 2>&1 || fail "could not write a PNG"
refused "--i0 must be a positive intensity" "$FM" radiograph "$IN/r.tif" --log --i0 0 --out "$OUT/p.png"
refused "--i0 applies to --log only" "$FM" radiograph "$IN/r.tif" --i0 100 --out "$OUT/p.png"
refused "--angles: Value 0 not in range" "$FM" drr --angles 0 --out "$OUT/d.png"
refused "--page: Value 2147483647 not in range" "$FM" radiograph "$IN/r.tif" --page 2147483647
refused "is not a TIFF (only a TIFF has pages)" "$FM" radiograph "$IN/r.png" --page 0
"$FM" radiograph "$IN/r.tif" --log --i0 300 >/dev/null || fail "--log --i0 300 refused"
echo PASS
