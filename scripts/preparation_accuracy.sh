#!/usr/bin/env bash
# Tracking accuracy against how a trial's frames are prepared (docs/tracking.md, "Preparing a
# trial's frames"): a bone of a real CT moving over the rest, simulated twice (raw detector
# intensities, `--signal linear`; a log-compressed display signal, `--signal log`), each tracked
# from its first frame's truth with the preparation its trial says and with the other one, and
# compared with the truth frame by frame. Prints the summary and a per-frame table (centre mm /
# rotation deg).
#   bash scripts/preparation_accuracy.sh [FM] [VOLUME LABELS BONE MOTION TABLE] [FRAMES]
set -euo pipefail
FM=${1:-build/app/fluoromatch}
D=${FM_DATA_DIR:-../shared/data}/totalseg-example-ct
VOLUME=${2:-$D/example_ct.nii.gz}
LABELS=${3:-$D/example_seg_fast_force_split.nii.gz}
BONE=${4:-hip_right}
MOTION=${5:-rotate:axis=x,angle=0:10}
TABLE=${6:-data/totalseg_bones.json}
FRAMES=${7:-20}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
run() {  # run NAME SIGNAL [track flags...]: tracks, compares, leaves $T/NAME.csv
    local name=$1 signal=$2; shift 2
    [ -d "$T/$signal" ] || "$FM" simulate --volume "$VOLUME" --labels "$LABELS" --label-table "$TABLE" --bone "$BONE" \
        --motion "$MOTION" --frames "$FRAMES" --signal "$signal" --out "$T/$signal" >/dev/null 2>&1
    "$FM" track --trial "$T/$signal/trial.json" --bone "$BONE" --start "$T/$signal/${BONE}_start.tra" \
        --out "$T/$name.tra" "$@" 2>/dev/null | grep "^cam1 " | sed "s/^cam1 */$name: /"
    "$FM" compare --truth "$T/$signal/${BONE}_truth.tra" --tra "$T/$name.tra" --trial "$T/$signal/trial.json" \
        --bone "$BONE" --csv "$T/$name.csv" | grep -E "^within|^  centre|^  rotation" | sed "s/^/    /"
}
run raw-log linear                               # the trial's (and the default for 16-bit raw frames)
run raw-invert linear --invert --exclude-below 0  # what every trial got before
run display-invert log                           # the trial's
run display-log log --log                        # the 16-bit default, had the trial not said
echo
echo "| frame | raw, log (mm / deg) | raw, inverted | display, inverted | display, log |"
echo "|---|---|---|---|---|"
paste -d, "$T/raw-log.csv" "$T/raw-invert.csv" "$T/display-invert.csv" "$T/display-log.csv" | tail -n +2 |
    awk -F, -v n=16 '{ printf "| %s |", $1; for (k = 0; k < 4; ++k) printf " %.3f / %.3f |", $(3 + k * n), $(4 + k * n); print "" }'
