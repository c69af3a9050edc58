#!/usr/bin/env bash
# `drr --spectrum` (realistic radiographs) from the command line:
#  1. a 16-bit TIFF of I/I0 that `radiograph` reads back as 16-bit, open field near 50000;
#  2. the same bytes for the same seed (any thread count), other bytes for another seed;
#     materials from a label map (--labels) give another image than by HU;
#  3. refusals: the detector options without --spectrum, --spectrum with a batch, --threshold or
#     --values with it, a volume not in HU, a bad spectrum, a tube voltage outside TASMIP.
set -uo pipefail
FM=$1
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
run() { "$FM" drr --volume phantom:knee --pose 0,0,0,30,10,0 --size 96x80 --spectrum 80 "$@"; }

out=$(run --intensity --photons 2000 --blur 0.5 --scatter 0.2 --out "$T/a.tif" --threads 1) || fail "exited $?: $out"
grep -q "^spectrum  80 kVp tungsten (TASMIP), 2.50 mm Al, 24 bins of 3.0 keV" <<<"$out" || fail "spectrum line: $out"
grep -q "16-bit, 50000 counts per unit of I/I0" <<<"$out" || fail "16-bit TIFF: $out"
info=$("$FM" radiograph "$T/a.tif" --out "$T/a.png") || fail "radiograph could not read it: $info"
grep -q "16-bit" <<<"$info" && grep -q "size         96 x 80" <<<"$info" || fail "read back: $info"
max=$(sed -n 's/^stored *min [0-9]* *max \([0-9]*\)$/\1/p' <<<"$info")
[ "$max" -gt 48000 ] && [ "$max" -lt 60000 ] || fail "open field $max, not near 50000 with noise: $info"

run --photons 500 --seed 4 --out "$T/b1.tif" --threads 1 >/dev/null || fail "seed 4, 1 thread"
run --photons 500 --seed 4 --out "$T/b2.tif" --threads 2 >/dev/null || fail "seed 4, 2 threads"
run --photons 500 --seed 5 --out "$T/b3.tif" --threads 2 >/dev/null || fail "seed 5"
cmp -s "$T/b1.tif" "$T/b2.tif" || fail "the same seed gave other bytes on 2 threads"
cmp -s "$T/b1.tif" "$T/b3.tif" && fail "another seed gave the same bytes"
run --raw "$T/c.mha" >/dev/null || fail "--raw"
# Materials from a label map: the labelled voxels are bone (another image than by HU).
out=$(run --labels phantom:knee --raw "$T/d.mha") || fail "--labels: $out"
grep -q "^materials cortical bone where phantom:knee labels a voxel" <<<"$out" || fail "materials line: $out"
cmp -s "$T/c.mha" "$T/d.mha" && fail "materials from the labels gave the image of materials from HU"

expect_error() {  # expect_error TEXT args...
    local text=$1; shift
    if "$FM" drr "$@" >"$T/out" 2>&1; then fail "'drr $*' succeeded"; fi
    grep -q -- "$text" "$T/out" || { cat "$T/out"; fail "'drr $*' did not say '$text'"; }
}
expect_error "--photons applies to a realistic radiograph" --volume phantom:knee --pose 0,0,0,0,0,0 --photons 100 --out "$T/x.png"
expect_error "--blur applies to a realistic radiograph" --volume phantom:knee --pose 0,0,0,0,0,0 --blur 1 --out "$T/x.png"
expect_error "renders one view" --volume phantom:knee --pose 0,0,0,0,0,0 --angles 3 --spectrum 80 --out "$T/x.png"
expect_error "--threshold does not apply" --volume phantom:knee --pose 0,0,0,0,0,0 --spectrum 80 --threshold 200 --out "$T/x.png"
expect_error "--values does not apply" --volume phantom:knee --pose 0,0,0,0,0,0 --spectrum 80 --values mu --out "$T/x.png"
expect_error "needs a CT in HU" --volume phantom:sphere --pose 0,0,0,0,0,0 --spectrum 80 --out "$T/x.png"
expect_error "outside TASMIP" --volume phantom:knee --pose 0,0,0,0,0,0 --spectrum 200 --out "$T/x.png"
expect_error "unknown \"kv\"" --volume phantom:knee --pose 0,0,0,0,0,0 --spectrum 80,kv=3 --out "$T/x.png"
expect_error "photons per pixel" --volume phantom:knee --pose 0,0,0,0,0,0 --spectrum 80 --electronic-noise 3 --out "$T/x.png"
echo "spectrum: ok"
