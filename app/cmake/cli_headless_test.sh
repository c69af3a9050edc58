#!/usr/bin/env bash
# The headless paths of the CLI, with no display:
#  1. `fluoromatch screenshot` writes a PNG of the requested size, and two runs give the same
#     bytes (deterministic);
#  2. `fluoromatch app` without DISPLAY says so and writes a headless screenshot (exit 0);
#  3. a volume that cannot be read fails with the reader's message (exit 1), no PNG.
#  4. geometry --geometry with --volume is refused (the volume would be ignored).
#  5. a --reference-pose or --pose the sliders cannot reach is refused, not clamped.
set -uo pipefail
FM=$1
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
png_size() { python3 -c "import struct,sys; d=open(sys.argv[1],'rb').read(24); \
assert d[:8]==b'\x89PNG\r\n\x1a\n'; print('%dx%d' % struct.unpack('>II', d[16:24]))" "$1"; }

"$FM" screenshot --out "$OUT/a.png" --size 640x400 --seed 5 || fail "screenshot exited $?"
"$FM" screenshot --out "$OUT/b.png" --size 640x400 --seed 5 || fail "second screenshot exited $?"
[ "$(png_size "$OUT/a.png")" = "640x400" ] || fail "screenshot is $(png_size "$OUT/a.png"), not 640x400"
cmp -s "$OUT/a.png" "$OUT/b.png" || fail "two identical screenshot runs differ"

msg=$(env -u DISPLAY -u WAYLAND_DISPLAY "$FM" app --headless-out "$OUT/fallback.png" 2>&1)
rc=$?
echo "$msg"
[ $rc -eq 0 ] || fail "app without a display exited $rc"
grep -q "no display" <<<"$msg" || fail "app without a display did not say so"
[ -s "$OUT/fallback.png" ] || fail "app without a display wrote no screenshot"

msg=$("$FM" screenshot --out "$OUT/bad.png" --volume "$OUT/missing.nii.gz" 2>&1)
rc=$?
echo "$msg"
[ $rc -eq 1 ] || fail "an unreadable volume gave exit $rc, not 1"
grep -q "missing.nii.gz" <<<"$msg" || fail "the error does not name the file"
[ ! -e "$OUT/bad.png" ] || fail "a PNG was written for an unreadable volume"

# 4. geometry: a geometry file fixes the scene, so a --volume beside it is refused, not ignored.
"$FM" geometry --pose 0,0,0,0,0,0 --center 0,0,0 --out "$OUT/g.json" || fail "geometry --pose exited $?"
msg=$("$FM" geometry --geometry "$OUT/g.json" --volume phantom:knee 2>&1)
rc=$?
[ $rc -ne 0 ] || fail "geometry --geometry with --volume was accepted (the volume would be ignored)"
grep -q "excludes" <<<"$msg" || fail "the refusal does not say the options exclude each other: $msg"
"$FM" geometry --geometry "$OUT/g.json" > /dev/null || fail "geometry --geometry alone exited $?"
# 5. poses beyond the sliders' reach (the knee's translation range is well under 500 mm).
msg=$("$FM" screenshot --out "$OUT/far.png" --reference-pose 500,0,0,0,0,0 2>&1)
rc=$?
[ $rc -eq 1 ] || fail "an unreachable --reference-pose gave exit $rc, not 1"
grep -q "reference-pose: x offset 500 mm is outside the slider range" <<<"$msg" \
    || fail "the refusal does not name the parameter and range: $msg"
[ ! -e "$OUT/far.png" ] || fail "a PNG was written for an unreachable reference pose"
msg=$("$FM" screenshot --out "$OUT/far.png" --pose 0,0,-900,0,0,0 2>&1)
rc=$?
[ $rc -eq 1 ] || fail "an unreachable --pose gave exit $rc, not 1"
grep -q "pose: z offset -900 mm" <<<"$msg" || fail "the --pose refusal is unclear: $msg"
echo PASS
