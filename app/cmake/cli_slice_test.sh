#!/usr/bin/env bash
# The MRI slice commands (docs/mri.md):
#  1. geometry --slice prints the documented JSON, exactly;
#  2. slice writes the PNG, raw values and mask, the same bytes on a second run;
#  3. a plane that misses the volume gives an empty slice and a message (exit 0), not NaN;
#  4. register --slice finds a hidden slice pose (mTRE below 1 mm);
#  5. nonsensical slice options are refused, naming the option;
#  6. evaluate --slice runs the van de Kraats protocol: one row per start, each start's initial
#     mTRE inside its bin, the same registrations on a second run.
set -uo pipefail
FM=$1
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# 1. The zero pose around the origin: a coronal slice, u = +x (left), v = -z (feet).
json=$("$FM" geometry --slice --center 0,0,0 --pose 0,0,0,0,0,0 --size 5x3 --spacing 2 --thickness 1.5) \
    || fail "geometry --slice exited $?"
expected='{
  "origin": [-4, 0, 2],
  "u": [1, 0, 0],
  "v": [0, 0, -1],
  "spacing": [2, 2],
  "size": [5, 3],
  "thickness": 1.5
}'
[ "$json" = "$expected" ] || fail "geometry --slice printed
$json"

# 2. Deterministic outputs.
for run in a b; do
    "$FM" slice --volume phantom:sphere --pose 3,-2,5,30,20,10 --size 64x48 --spacing 2 \
        --out "$OUT/$run.png" --raw "$OUT/$run.mha" --mask "$OUT/$run-mask.png" > "$OUT/$run.txt" \
        || fail "slice exited $?"
done
cmp -s "$OUT/a.png" "$OUT/b.png" && cmp -s "$OUT/a.mha" "$OUT/b.mha" && \
    cmp -s "$OUT/a-mask.png" "$OUT/b-mask.png" || fail "two identical slice runs differ"
grep -q "data      [1-9][0-9]* of 3072 pixels" "$OUT/a.txt" || fail "no data pixels: $(cat "$OUT/a.txt")"

# 3. A plane beyond the volume.
msg=$("$FM" slice --volume phantom:sphere --pose 0,900,0,0,0,0 --out "$OUT/none.png" --raw "$OUT/none.mha" 2>&1)
rc=$?
[ $rc -eq 0 ] || fail "an empty slice exited $rc"
grep -q "misses the volume" <<<"$msg" || fail "no message for an empty slice: $msg"
grep -q "data      0 of" <<<"$msg" || fail "an empty slice reports data: $msg"
[ -s "$OUT/none.png" ] || fail "no PNG for an empty slice"
if grep -qa "nan" "$OUT/none.mha"; then fail "the empty slice's header mentions NaN"; fi

# 4. Registration of a hidden slice (small budget, small grid: seconds).
out=$("$FM" register --slice --volume phantom:knee --reference-pose 3,-2,4,20,10,5 \
      --start 0,0,0,15,5,0 --size 96x96 --spacing 2.5 --threads 2 2>/dev/null) \
    || fail "register --slice exited $?"
echo "$out" | tail -3
final=$(sed -n 's/^mTRE .*-> final \([0-9.]*\) mm.*/\1/p' <<<"$out")
[ -n "$final" ] || fail "register --slice printed no mTRE"
python3 -c "import sys; sys.exit(0 if float('$final') < 1.0 else 1)" || fail "final mTRE $final mm"
# How sure, without the truth: searches from independent starts agree and the slice matches the
# reference as a slice of the volume does (its similarity against a perfect match's).
grep -q "^verdict     ok: 2 of 2 searches from different starts end here; similarity 1.00 of a perfect match's" <<<"$out" ||
    fail "register --slice: no ok verdict with its reasons: $out"
grep -q "^uncertainty x .* mm, y .* mm, z .* mm, azimuth" <<<"$out" || fail "register --slice: no uncertainty line: $out"

# 5. Bad input, named.
msg=$("$FM" slice --volume phantom:sphere --thickness -1 --out "$OUT/t.png" 2>&1)
[ $? -ne 0 ] && grep -q "thickness" <<<"$msg" || fail "negative thickness not refused: $msg"
msg=$("$FM" slice --volume phantom:sphere --size 0x10 --out "$OUT/t.png" 2>&1)
[ $? -ne 0 ] && grep -q -- "--size" <<<"$msg" || fail "zero size not refused: $msg"
msg=$("$FM" slice --volume phantom:sphere --interpolation quintic --out "$OUT/t.png" 2>&1)
[ $? -ne 0 ] && grep -q "quintic" <<<"$msg" || fail "unknown interpolation not refused: $msg"
msg=$("$FM" geometry --slice --center 0,0,0 --film 100x100 2>&1)
[ $? -ne 0 ] && grep -q -- "--film" <<<"$msg" || fail "geometry --slice --film not refused: $msg"
msg=$("$FM" register --reference-pose 0,0,0,0,0,0 --thickness 3 2>&1)
[ $? -ne 0 ] && grep -q -- "--slice" <<<"$msg" || fail "--thickness without --slice not refused: $msg"
msg=$("$FM" slice --volume phantom:sphere --raw "$OUT/s.png" 2>&1)
[ $? -ne 0 ] && grep -q -- "--raw .*cannot hold the exact values" <<<"$msg" || fail "slice --raw .png not refused: $msg"
msg=$("$FM" slice --volume phantom:sphere --raw "$OUT/nofolder/s.mha" 2>&1)
[ $? -ne 0 ] && grep -q -- "--raw .*does not exist" <<<"$msg" || fail "slice --raw in a missing folder not refused: $msg"
[ ! -e "$OUT/t.png" ] && [ ! -e "$OUT/s.png" ] || fail "a PNG was written for refused options"
# One default interpolation: slice samples as register --slice compares (cubic B-spline).
"$FM" slice --volume phantom:sphere --pose 3,-2,5,30,20,10 --size 32x32 --raw "$OUT/d.mha" >/dev/null || fail "slice (default) failed"
"$FM" slice --volume phantom:sphere --pose 3,-2,5,30,20,10 --size 32x32 --interpolation cubic --raw "$OUT/c.mha" >/dev/null || fail "slice cubic failed"
"$FM" slice --volume phantom:sphere --pose 3,-2,5,30,20,10 --size 32x32 --interpolation linear --raw "$OUT/l.mha" >/dev/null || fail "slice linear failed"
cmp -s "$OUT/d.mha" "$OUT/c.mha" || fail "slice's default is not register --slice's (cubic)"
cmp -s "$OUT/d.mha" "$OUT/l.mha" && fail "cubic and linear slices are identical: the check cannot tell them apart"
grep -q "interpolation TEXT=cubic" <<<"$("$FM" register --help)" || fail "register --slice's default is no longer cubic"
# --raw .tif: float32 TIFF of exact values.
"$FM" slice --volume phantom:sphere --size 16x16 --raw "$OUT/s.tif" >/dev/null || fail "slice --raw .tif failed"
[ "$(head -c 4 "$OUT/s.tif" | od -An -tx1 | tr -d ' \n')" = "49492a00" ] || fail "slice --raw .tif is not a TIFF"
# 6. The slice evaluation (tiny: 1 start per bin, a coarse grid, a small budget).
for run in a b; do
    "$FM" evaluate --slice --volume phantom:knee --truth 3,-2,4,20,10,5 --methods cmaes \
        --starts 1 --size 48x48 --spacing 5 --threads 2 --budget 150 --levels 2,1 \
        --csv "$OUT/ev-$run.csv" > "$OUT/ev-$run.txt" 2>&1 || fail "evaluate --slice exited $?"
done
grep -q "capture range" "$OUT/ev-a.txt" || fail "no capture range: $(cat "$OUT/ev-a.txt")"
python3 - "$OUT/ev-a.csv" "$OUT/ev-b.csv" <<'PY' || fail "evaluate --slice CSV"
import csv, sys
runs = [list(csv.DictReader(open(p))) for p in sys.argv[1:]]
a, b = runs
assert len(a) == 4, f"{len(a)} rows, expected one per bin (0-2, 2-5, 5-10, 10-20 mm)"
for r in a:
    lo, hi, start = float(r["bin_low_mm"]), float(r["bin_high_mm"]), float(r["start_mtre_mm"])
    assert lo <= start <= hi, f"start mTRE {start} outside its bin {lo}-{hi}"
    assert r["success"] == ("1" if float(r["final_mtre_mm"]) < 1.0 else "0"), r
timeless = lambda rows: [{k: v for k, v in r.items() if "seconds" not in k} for r in rows]
assert timeless(a) == timeless(b), "two runs with one seed differ"
PY

echo PASS
