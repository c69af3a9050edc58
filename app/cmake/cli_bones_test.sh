#!/usr/bin/env bash
# One bone at a time on the command line (docs/bones.md):
#  1. on the real CT with its TotalSegmentator labels: drr --bone femur_right plus
#     drr --without femur_right equals the DRR of the whole CT, pixel for pixel (float);
#  2. info lists the labels with names, and the table's names the map lacks as "missing";
#  3. bad input: an unknown bone name, an empty label, a label map of another scan, --bone
#     without --labels: exit 1 with a message naming the problem, nothing written;
#  4. the knee phantom's own labels and connected components: per-bone DRR and meshes;
#  5. the app's --labels (headless screenshot): bones in the app, or exit 1 naming the
#     table's missing label, nothing written.
set -uo pipefail
FM=$1
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
DATA=${FM_DATA_DIR:-$(dirname "$0")/../../../shared/data}/totalseg-example-ct
CT=$DATA/example_ct.nii.gz
SEG=$DATA/example_seg_fast_force_split.nii.gz
printf '{"femur_left": 75, "femur_right": 76, "hip_left": 77, "hip_right": 78, "sacrum": 25, "not_in_this_scan": 200}' > "$OUT/table.json"

# Largest |a + b - whole| / max(whole) of three float32 .mha images.
additivity() { python3 - "$@" <<'PY'
import sys, struct, zlib
def read(path):
    data = open(path, 'rb').read()
    end = data.index(b'ElementDataFile = LOCAL\n') + len(b'ElementDataFile = LOCAL\n')
    raw = data[end:]
    if b'CompressedData = True' in data[:end]:
        raw = zlib.decompress(raw)
    return struct.unpack('<%df' % (len(raw) // 4), raw)
a, b, w = (read(p) for p in sys.argv[1:4])
peak = max(w)
print(max(abs(x + y - z) for x, y, z in zip(a, b, w)) / peak if peak > 0 else 1.0)
PY
}

if [ -f "$SEG" ]; then
    POSE=--pose=0,0,0,30,10,0
    common=(--volume "$CT" --size 96x96 "$POSE")
    "$FM" drr "${common[@]}" --raw "$OUT/whole.mha" > /dev/null || fail "drr of the whole CT exited $?"
    "$FM" drr "${common[@]}" --labels "$SEG" --label-table "$OUT/table.json" --bone femur_right \
        --raw "$OUT/bone.mha" > "$OUT/bone.log" || fail "drr --bone exited $?"
    grep -q "bone femur_right (label 76) alone" "$OUT/bone.log" || fail "drr --bone does not say which bone"
    "$FM" drr "${common[@]}" --labels "$SEG" --without 76 --raw "$OUT/rest.mha" > /dev/null \
        || fail "drr --without exited $?"
    err=$(additivity "$OUT/bone.mha" "$OUT/rest.mha" "$OUT/whole.mha")
    python3 -c "import sys; sys.exit(0 if float('$err') < 1e-5 else 1)" \
        || fail "bone + rest differs from the whole by $err of the peak"
    echo "bone + rest = whole to $err of the peak"
    # The crop is named as a crop; --center bone puts the bone in the middle of the film (its
    # image's centroid within 5% of the film's centre), where the CT's centre left it in a corner.
    grep -q "cropped to the bone" "$OUT/bone.log" || fail "drr --bone prints the crop as the volume"
    grep -q "^centre    the whole CT's" "$OUT/bone.log" || fail "drr --bone does not say where the film is centred"
    "$FM" drr "${common[@]}" --labels "$SEG" --label-table "$OUT/table.json" --bone femur_right \
        --center bone --raw "$OUT/centred.mha" > /dev/null || fail "drr --bone --center bone exited $?"
    offcentre() { python3 - "$1" <<'PY'
import sys, struct, zlib
data = open(sys.argv[1], 'rb').read()
end = data.index(b'ElementDataFile = LOCAL\n') + len(b'ElementDataFile = LOCAL\n')
raw = data[end:]
if b'CompressedData = True' in data[:end]:
    raw = zlib.decompress(raw)
v = struct.unpack('<%df' % (len(raw) // 4), raw)
n = 96
s = sum(v); cx = sum(v[i] * (i % n) for i in range(len(v))) / s; cy = sum(v[i] * (i // n) for i in range(len(v))) / s
print(max(abs(cx - (n - 1) / 2), abs(cy - (n - 1) / 2)) / n)
PY
    }
    far=$(offcentre "$OUT/bone.mha"); near=$(offcentre "$OUT/centred.mha")
    python3 -c "import sys; sys.exit(0 if float('$near') < 0.05 < float('$far') else 1)" \
        || fail "--center bone: the bone is $near of the film off centre (CT centre: $far)"
    msg=$("$FM" drr --center bone --out "$OUT/x.png" 2>&1); rc=$?
    [ $rc -eq 2 ] && grep -q "needs --bone" <<<"$msg" || fail "--center bone without --bone: exit $rc: $msg"

    msg=$("$FM" info "$CT" --labels "$SEG" --label-table "$OUT/table.json" 2>&1) || fail "info --labels exited $?"
    grep -Eq "76 femur_right +4396 voxels" <<<"$msg" || fail "info does not list femur_right with 4396 voxels"
    grep -q "not_in_this_scan.*missing" <<<"$msg" || fail "info does not report the missing label"

    msg=$("$FM" drr "${common[@]}" --labels "$SEG" --label-table "$OUT/table.json" --bone femur --out "$OUT/x.png" 2>&1)
    [ $? -eq 1 ] || fail "an unknown bone name was accepted"
    grep -q "known names:.*femur_right (76)" <<<"$msg" || fail "unknown bone: no list of names: $msg"
    msg=$("$FM" drr "${common[@]}" --labels "$SEG" --label-table "$OUT/table.json" --bone not_in_this_scan --out "$OUT/x.png" 2>&1)
    [ $? -eq 1 ] || fail "an empty bone was accepted"
    grep -q "has no voxel" <<<"$msg" || fail "empty bone: unclear message: $msg"
    # A label map around the world origin: 16 mm of nothing but label 1, which the CT (y from
    # -311 to -11 mm) does not reach.
    "$FM" convert --volume phantom:box,size=16 --out "$OUT/elsewhere.nii.gz" > /dev/null || fail "convert exited $?"
    msg=$("$FM" drr "${common[@]}" --labels "$OUT/elsewhere.nii.gz" --bone 1 --out "$OUT/x.png" 2>&1)
    [ $? -eq 1 ] || fail "the label map of another scan was accepted"
    grep -q "cannot be resampled" <<<"$msg" || fail "disjoint grid: unclear message: $msg"
    [ ! -e "$OUT/x.png" ] || fail "a PNG was written for bad input"

    # register --bone: femur_right moved 6 mm / 6 deg, registered alone, biplane, bones only.
    msg=$("$FM" register --volume "$CT" --labels "$SEG" --label-table "$OUT/table.json" --bone femur_right \
        --bone-motion 6,-5,5,6,-5,5 --biplane --no-rest 2>/dev/null) || fail "register --bone exited $?"
    final=$(sed -n 's/.*-> final \([0-9.]*\) mm.*/\1/p' <<<"$msg")
    python3 -c "import sys; sys.exit(0 if float('${final:-99}') < 1.0 else 1)" \
        || fail "register --bone: final mTRE ${final:-?} mm, not under 1 mm: $msg"
    echo "register --bone femur_right: final mTRE $final mm"
else
    [ "${CI:-}" = "true" ] && fail "shared data missing under CI: $SEG"
    echo "skipping the real-CT checks: $SEG not found"
fi

msg=$("$FM" register --bone femur 2>&1)
[ $? -eq 1 ] || fail "register --bone without --labels was accepted"
msg=$("$FM" drr --bone femur --out "$OUT/x.png" 2>&1)
[ $? -eq 1 ] || fail "--bone without --labels was accepted"
grep -q "needs --labels" <<<"$msg" || fail "--bone without --labels: unclear message: $msg"

KNEE=(--volume phantom:knee,size=64x64x70 --labels phantom:knee,size=64x64x70)
"$FM" drr "${KNEE[@]}" --bone tibia+fibula --size 64x64 --out "$OUT/tibia.png" > /dev/null \
    || fail "drr of the phantom's tibia exited $?"
"$FM" mesh "${KNEE[@]}" --bone patella --out "$OUT/patella.ply" > "$OUT/mesh.log" || fail "mesh --bone exited $?"
grep -q "1 component " "$OUT/mesh.log" || fail "the patella's mesh is not one piece: $(cat "$OUT/mesh.log")"
"$FM" mesh "${KNEE[@]}" --bone femur --mask --out "$OUT/femur.ply" > /dev/null || fail "mesh --mask exited $?"
msg=$("$FM" info phantom:knee,size=64x64x70 --labels components 2>&1) || fail "info --labels components exited $?"
[ "$(grep -c 'component [0-9]' <<<"$msg")" -ge 4 ] || fail "components: fewer than 4 bones: $msg"
"$FM" screenshot --volume phantom:knee,size=64x64x70 --labels components --size 640x400 \
    --out "$OUT/app.png" > /dev/null || fail "screenshot --labels components exited $?"
[ -s "$OUT/app.png" ] || fail "screenshot --labels wrote nothing"
printf '{"femur": 1, "not_here": 200}' > "$OUT/knee_table.json"
msg=$("$FM" screenshot --volume phantom:knee,size=64x64x70 --labels phantom:knee,size=64x64x70 \
    --label-table "$OUT/knee_table.json" --size 640x400 --out "$OUT/bad.png" 2>&1)
[ $? -eq 1 ] || fail "screenshot --label-table naming a missing label was accepted"
grep -q "not_here (200)" <<<"$msg" || fail "missing label: unclear message: $msg"
[ -e "$OUT/bad.png" ] && fail "a screenshot was written despite bad labels"
msg=$("$FM" app --label-table "$OUT/knee_table.json" --frames 1 2>&1)
[ $? -eq 2 ] || fail "app --label-table without --labels was accepted: $msg"
echo PASS
