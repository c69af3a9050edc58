#!/usr/bin/env bash
# Issue 31's proof, shortened: example_ct's right femur (a stub cut by the scan's end, 3 mm voxels)
# flexing 0-30 deg over the rest of the CT in 10 frames (3.3 deg apart; the documented proof has
# 20), two cameras 80 deg apart, 10^4 photons, tracked from frame 0's truth: `compare` finds every
# frame within 0.5 mm / 0.5 deg (docs/tracking.md, "Accuracy against photon count"). Release only
# (~10 s there); shared data (skips without it, fails under CI=true).
set -uo pipefail
FM=$1
. "$(dirname "$0")/simulated_femur.sh"
simulate_femur "$T/s"
out=$("$FM" track --trial "$T/s/trial.json" --bone femur_right --start "$T/s/femur_right_start.tra" \
    --out "$T/t.tra" 2>&1) || fail "track exited $?: $out"
out=$("$FM" compare --truth "$T/s/femur_right_truth.tra" --tra "$T/t.tra" --trial "$T/s/trial.json" \
    --bone femur_right) || fail "compare exited $?: $out"
grep -q "0.5 mm and 0.5 deg: 100.0 % (10 of 10)" <<<"$out" || fail "not every frame within 0.5 mm / 0.5 deg: $out"
echo "simulate femur: ok"
