#!/usr/bin/env bash
# CLI conventions (docs: README "Exit codes"): did-you-mean for misspelt commands and options,
# exit codes 0/1/2, output format by extension (checked by magic bytes), output folders and
# formats checked before any work, unit detection said out loud (and overridable), the
# all-zero DRR warning, and batch DRRs (--angles, --poses) identical to single renders.
set -uo pipefail
FM=$1
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
magic() { python3 -c "import sys; print(open(sys.argv[1],'rb').read(int(sys.argv[2])).hex())" "$1" "$2"; }

# 1. Misspellings and exit codes.
msg=$("$FM" drrr 2>&1); rc=$?
[ $rc -eq 2 ] || fail "unknown command exited $rc, not 2"
grep -q 'unknown command "drrr"; did you mean "drr"?' <<<"$msg" || fail "no suggestion: $msg"
msg=$("$FM" drr --otu x.png 2>&1); rc=$?
[ $rc -eq 2 ] || fail "unknown option exited $rc, not 2"
grep -q 'unknown option --otu for drr; did you mean --out?' <<<"$msg" || fail "no suggestion: $msg"
msg=$("$FM" drr --values foo 2>&1); rc=$?
[ $rc -eq 2 ] || fail "a bad --values exited $rc, not 2"
"$FM" drr --help > /dev/null || fail "--help exited $?"
msg=$("$FM" drr --volume "$OUT/none.nii" --out "$OUT/a.png" 2>&1); rc=$?
[ $rc -eq 1 ] || fail "a missing volume exited $rc, not 1"

# 2. The format the extension names.
for ext in png jpg tif mha; do
    "$FM" drr --out "$OUT/v.$ext" > /dev/null || fail "drr --out v.$ext exited $?"
done
[ "$(magic "$OUT/v.png" 4)" = "89504e47" ] || fail "v.png is not a PNG"
[ "$(magic "$OUT/v.jpg" 2)" = "ffd8" ] || fail "v.jpg is not a JPEG: $(magic "$OUT/v.jpg" 4)"
[ "$(magic "$OUT/v.tif" 4)" = "49492a00" ] || fail "v.tif is not a little-endian TIFF"
head -c 64 "$OUT/v.mha" | grep -q "ObjectType" || fail "v.mha is not a MetaImage"
"$FM" drr --raw "$OUT/r.tif" > /dev/null || fail "drr --raw r.tif exited $?"
[ "$(magic "$OUT/r.tif" 4)" = "49492a00" ] || fail "r.tif is not a TIFF"

# 3. Checked before any work: no volume is loaded for a name or folder that cannot be written.
for bad in "$OUT/v.bmp" "$OUT/missing/v.png"; do
    msg=$("$FM" drr --out "$bad" 2>&1); rc=$?
    [ $rc -eq 1 ] || fail "--out $bad exited $rc, not 1"
    grep -q "$bad" <<<"$msg" || fail "the error does not name the user's path: $msg"
    grep -q "^volume" <<<"$msg" && fail "the volume was loaded before refusing $bad"
done
msg=$("$FM" drr --raw "$OUT/r.png" 2>&1); rc=$?
[ $rc -eq 1 ] || fail "--raw r.png (8 bits) was accepted"

# 4. Units: a bone crop without units and background 0 (as Autoscoper's) is not HU.
python3 - "$OUT/crop.mha" <<'PY'
import struct, sys
n = 24
vals = [1200.0 if 8 <= i < 16 and 8 <= j < 16 and 8 <= k < 16 else 0.0
        for k in range(n) for j in range(n) for i in range(n)]
with open(sys.argv[1], "wb") as f:
    f.write(b"ObjectType = Image\nNDims = 3\nDimSize = 24 24 24\nElementSpacing = 2 2 2\n"
            b"ElementType = MET_FLOAT\nElementDataFile = LOCAL\n")
    f.write(struct.pack("<%df" % len(vals), *vals))
PY
msg=$("$FM" drr --volume "$OUT/crop.mha" --out "$OUT/crop.png" 2>&1) || fail "drr on the crop exited $?"
grep -q "values    auto: not HU" <<<"$msg" || fail "the unit decision is not said: $msg"
msg=$("$FM" drr --volume "$OUT/crop.mha" --values mu --out "$OUT/crop-mu.png" 2>&1) || fail "--values mu exited $?"
grep -q "warning: --values mu converts the values as HU" <<<"$msg" || fail "no warning for mu on non-HU: $msg"
msg=$("$FM" drr --out "$OUT/knee.png" 2>&1) || fail "drr on the knee exited $?"
grep -q "values    auto: HU" <<<"$msg" || fail "the knee phantom is not taken as HU: $msg"

# 5. A DRR that misses the volume is all zero: said.
msg=$("$FM" drr --pose 150,150,150,0,0,0 --film 20x20 --out "$OUT/empty.png" 2>&1) || fail "off-film drr exited $?"
grep -q "all zero" <<<"$msg" || fail "no warning for an all-zero DRR: $msg"

# 6. Batches: numbered outputs, each identical to the single render of its view.
"$FM" drr --size 64x64 --angles 3 --angle-step 90 --raw "$OUT/s.mha" > "$OUT/sweep.log" || fail "sweep exited $?"
for i in 0 1 2; do
    "$FM" drr --size 64x64 --pose 0,0,0,$((i * 90)),0,0 --raw "$OUT/one$i.mha" > /dev/null || fail "single drr exited $?"
    cmp -s "$OUT/one$i.mha" "$OUT/s_00$i.mha" || fail "sweep view $i differs from its single render"
done
grep -c "^wrote" "$OUT/sweep.log" | grep -q '^3$' || fail "the sweep did not report 3 outputs"
[ "$(grep -c '^prepare' "$OUT/sweep.log")" -eq 1 ] || fail "the volume was prepared more than once"
printf '# two views\n0 0 0 90 0 0\n5,0,0,0,10,0\n' > "$OUT/views.txt"
"$FM" drr --size 64x64 --poses "$OUT/views.txt" --raw "$OUT/p.mha" --out "$OUT/p.png" > /dev/null || fail "--poses exited $?"
cmp -s "$OUT/one1.mha" "$OUT/p_000.mha" || fail "--poses line 1 differs from its single render"
"$FM" drr --size 64x64 --pose 5,0,0,0,10,0 --raw "$OUT/two.mha" > /dev/null || fail "single drr exited $?"
cmp -s "$OUT/two.mha" "$OUT/p_001.mha" || fail "--poses line 2 differs from its single render"
[ -f "$OUT/p_001.png" ] || fail "--poses did not write numbered PNGs"
printf '0 0 0 0 0\n' > "$OUT/bad.txt"
msg=$("$FM" drr --poses "$OUT/bad.txt" --out "$OUT/b.png" 2>&1); rc=$?
[ $rc -eq 1 ] || fail "a malformed views file exited $rc"
grep -q "bad.txt:1" <<<"$msg" || fail "the error does not name the line: $msg"
# 7. Exit codes (README "Exit codes"), a table: a bad option value or an option the mode does
# not take is a usage error (2), said before any volume is loaded; a bad file is 1.
while IFS='|' read -r code text args; do
    [ -n "$code" ] || continue
    read -r -a argv <<<"$args"
    msg=$("$FM" "${argv[@]}" 2>&1); rc=$?
    [ "$rc" -eq "$code" ] || fail "'$args' exited $rc, not $code: $msg"
    grep -q -- "$text" <<<"$msg" || fail "'$args' did not say '$text': $msg"
    if [ "$code" -eq 2 ] && grep -q "^volume \|^values " <<<"$msg"; then fail "'$args' loaded the volume before refusing"; fi
done <<TABLE
2|expected 6 comma-separated numbers|drr --pose 0,0,0,0,0 --out $OUT/x.png
2|did you mean 'cmaes'?|register --reference-pose 1,2,3,4,5,6 --method cmaess
2|nm is the local polish|register --reference-pose 1,2,3,4,5,6 --method nm
2|unknown polish method 'pso' (nm or cmaes)|register --reference-pose 1,2,3,4,5,6 --polish pso
2|did you mean 'gncc'?|register --reference-pose 1,2,3,4,5,6 --similarity gnc
2|--start: pose|register --reference-pose 1,2,3,4,5,6 --start 1,2
2|--truth: pose|register --reference $OUT/v.png --geometry g.json --truth 1
2|--thickness is for register --slice|register --reference-pose 1,2,3,4,5,6 --thickness 2
2|--pose: pose|slice --pose 1,2 --out $OUT/s.png
2|--truth: pose|evaluate --truth 1,2,3
2|--pose: pose|screenshot --pose 1,2 --out $OUT/u.png
2|--budget|register --reference-pose 1,2,3,4,5,6 --budget 0
2|--seed|register --reference-pose 1,2,3,4,5,6 --seed -1
2|--values|drr --values foo --out $OUT/x.png
2|--volume does not apply to screenshot --trial|screenshot --trial t.json --volume phantom:sphere --out $OUT/x.png
2|--invert does not apply to app (the matching game|app --volume phantom:knee --invert --headless-out $OUT/y.png
2|unknown .tra form 'rows' (matrix or xyzypr)|register --reference r.tif --camera c.txt --model m.stl --start s.tra --tra-form rows
1|none.nii|drr --volume $OUT/none.nii --out $OUT/a.png
1|does not exist|drr --out $OUT/missing/v.png
0||drr --pose 0,0,0,0,0,0 --size 16x16 --out $OUT/ok.png
TABLE
echo PASS
