#!/usr/bin/env bash
# Tracking accuracy against photon count on simulated trials (docs/tracking.md, "Simulated
# trials"): for each photon count, `simulate` a trial, `track` it from its first frame's truth and
# `compare` it with the truth; one table row per count.
#   [FM_SIMULATE_ARGS="--azimuth -40 ..."] bash scripts/simulate_accuracy.sh [FM] [VOLUME LABELS BONE MOTION [TABLE]]
# Default: the knee phantom's femur flexing 0-40 deg over 20 frames, two cameras 80 deg apart.
# FM_SIMULATE_ARGS: more `simulate` options (word-split), the same for every row.
set -euo pipefail
FM=${1:-build/app/fluoromatch}
VOLUME=${2:-phantom:knee}
LABELS=${3:-phantom:knee}
BONE=${4:-femur}
MOTION=${5:-rotate:axis=x,angle=0:40}
TABLE=${6:-}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
echo "| photons | centre RMS mm | centre worst mm | rotation RMS deg | rotation worst deg | within 0.5 mm / 0.5 deg | track s/frame |"
echo "|---|---|---|---|---|---|---|"
for photons in 0 100000 10000 3000 1000 300 100; do
    extra=()
    [ -n "$TABLE" ] && extra=(--label-table "$TABLE")
    # shellcheck disable=SC2206
    extra+=(${FM_SIMULATE_ARGS:-})
    "$FM" simulate --volume "$VOLUME" --labels "$LABELS" --bone "$BONE" --motion "$MOTION" --frames 20 \
        --photons "$photons" --out "$T/s$photons" "${extra[@]}" >/dev/null 2>&1
    start=$(date +%s.%N)
    "$FM" track --trial "$T/s$photons/trial.json" --bone "$BONE" --start "$T/s$photons/${BONE}_start.tra" \
        --out "$T/s$photons/t.tra" >/dev/null 2>&1
    seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print (b - a) / 20 }')
    out=$("$FM" compare --truth "$T/s$photons/${BONE}_truth.tra" --tra "$T/s$photons/t.tra" \
        --trial "$T/s$photons/trial.json" --bone "$BONE")
    c=($(sed -n 's/^  centre *\(.*\)$/\1/p' <<<"$out"))
    r=($(sed -n 's/^  rotation *\(.*\)$/\1/p' <<<"$out"))
    w=$(sed -n 's/.*0.5 mm and 0.5 deg: \([0-9.]* %\).*/\1/p' <<<"$out")
    printf "| %s | %s | %s | %s | %s | %s | %.2f |\n" "$([ "$photons" = 0 ] && echo "no noise" || echo "$photons")" \
        "${c[2]}" "${c[3]}" "${r[2]}" "${r[3]}" "$w" "$seconds"
done
