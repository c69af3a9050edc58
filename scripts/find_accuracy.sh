#!/usr/bin/env bash
# Pose from nothing on the JTML frames (docs/find.md): for each search space given (default: the
# ones docs/find.md tabulates), both implants of each frame registered with no start by
# `fluoromatch register`; per frame and implant the error against the .jts (in-plane mm, rotation
# deg, as compare measures them in the camera's axes), the verdict, and the time per stage.
#   FM_DATA_DIR=/work/shared/data bash scripts/find_accuracy.sh ["tilt=35" "tilt=50,depth=0.1:0.95" ...]
set -euo pipefail
cd "$(dirname "$0")/.."
FM=${FM:-build/app/fluoromatch}
D=${FM_DATA_DIR:-../shared/data}/jtml-kneel-tka-fluoro
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
spaces=("$@")
[ ${#spaces[@]} -gt 0 ] || spaces=("tilt=35" "tilt=20" "tilt=50" "roll=90" "depth=0.5:0.92" "depth=0.1:0.95")
printf "%-22s %-5s %-4s %9s %9s %9s %-9s %8s %8s %8s %8s %8s\n" space frame imp inplane_mm depth_mm rot_deg verdict scan_s refine_s finish_s found_s wall_s
for space in "${spaces[@]}"; do
    for f in 0 1 2; do
        img=$D/AT_K1_V1_0$((16 + f))0.tif
        start=$(date +%s.%N)
        "$FM" register --reference "$img" --camera "$D/calibration.txt" --model "$D/KR_right_7_fem.stl" \
            --model "$D/KR_right_6_tib.stl" --invert --frame $f --find-space "$space" \
            --out "$OUT/fem.jts" --out "$OUT/tib.jts" > "$OUT/log" 2>&1 || true
        wall=$(echo "$(date +%s.%N) - $start" | bc)
        for imp in fem tib; do
            python3 - "$OUT/log" "$OUT/$imp.jts" "$D/$imp.jts" "$D/calibration.txt" "$f" "$imp" "$space" "$wall" <<'PY'
import math, re, sys
log, found, truth, cal, frame, imp, space, wall = sys.argv[1:9]
frame = int(frame)
text = open(log).read()
# This implant's block of the log.
blocks = text.split("\nmodel       ")
block = next((b for b in blocks[1:] if ("fem.stl" if imp == "fem" else "tib.stl") in b.split("\n")[0]), "")
def stage(name):
    m = re.search(r"^found       %s +([0-9.]+) s" % name, block, re.M)
    return float(m.group(1)) if m else float("nan")
verdict = (re.search(r"^verdict     (\w+)", block, re.M) or [None, "none"])[1]
def row(path):
    try:
        lines = open(path).read().split("\n")[2:]
        return [float(x) for x in lines[frame].split(",")]
    except Exception:
        return None
a, b = row(found), row(truth)
if a is None:
    print("%-22s %-5d %-4s %9s %9s %9s %-9s" % (space, frame, imp, "-", "-", "-", verdict))
    sys.exit(0)
# The camera looks along -z (JointTrack): in-plane = x, y; depth = z.
def R(z, x, y):
    z, x, y = map(math.radians, (z, x, y))
    Rz = [[math.cos(z), -math.sin(z), 0], [math.sin(z), math.cos(z), 0], [0, 0, 1]]
    Rx = [[1, 0, 0], [0, math.cos(x), -math.sin(x)], [0, math.sin(x), math.cos(x)]]
    Ry = [[math.cos(y), 0, math.sin(y)], [0, 1, 0], [-math.sin(y), 0, math.cos(y)]]
    mul = lambda A, B: [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return mul(mul(Rz, Rx), Ry)
Ra, Rb = R(a[3], a[4], a[5]), R(b[3], b[4], b[5])
tr = sum(Ra[k][i] * Rb[k][i] for i in range(3) for k in range(3))
rot = math.degrees(math.acos(max(-1.0, min(1.0, (tr - 1) / 2))))
# The .jts position is the model origin; in-plane error of the origin's projection direction is close
# to the pivot's for these sub-degree rotation errors.
inplane = math.hypot(a[0] - b[0], a[1] - b[1])
found_s = stage("templates") + stage("scan") + stage("refine") + stage("finish")
print("%-22s %-5d %-4s %9.3f %9.2f %9.3f %-9s %8.2f %8.2f %8.2f %8.2f %8s" % (
    space, frame, imp, inplane, a[2] - b[2], rot, verdict, stage("scan"), stage("refine"), stage("finish"), found_s, wall))
PY
        done
    done
done
