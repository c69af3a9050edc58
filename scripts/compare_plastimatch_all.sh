#!/usr/bin/env bash
# Issue 15's DRR matrix: scripts/compare_plastimatch.sh on every real CT of the data folder, at
# 256^2 and 512^2, with 1 and 2 threads, then one table of plastimatch / ours per CT, size and
# thread count (the four views in mu and raw values), and the smallest ratio of all.
#
#   bash scripts/compare_plastimatch_all.sh [--repeat N] [--out DIR] [--only NAME[,NAME]]
#     --repeat N   alternating runs per view and tool (default 5; see compare_plastimatch.sh)
#     --out DIR    keep each run's full report in DIR (default: a temporary folder)
#     --only LIST  only these CTs (names as in the table: example_ct, aorta_crop, ...)
#     --fluoromatch PATH   executable (default: build/app/fluoromatch; a copy keeps a long run
#                  safe from rebuilds)
#
# The data folder is $FM_DATA_DIR (default ../shared/data). The GE gantry-tilt series is
# resampled by our reader onto an oblique grid, which plastimatch cannot place (it ignores
# direction cosines): both tools then render the same voxels with identity axes. The wrist
# radius is a CT crop with its surroundings zeroed (Autoscoper's bone volume).
set -euo pipefail
cd "$(dirname "$0")/.."

DATA=${FM_DATA_DIR:-../shared/data}
REPEAT=5
OUT=""
ONLY=""
FM=build/app/fluoromatch
while [ $# -gt 0 ]; do
    case "$1" in
        --repeat) REPEAT=$2; shift 2 ;;
        --out) OUT=$2; shift 2 ;;
        --only) ONLY=$2; shift 2 ;;
        --fluoromatch) FM=$2; shift 2 ;;
        -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
        *) echo "compare_plastimatch_all: unknown option $1" >&2; exit 2 ;;
    esac
done
if [ -z "$OUT" ]; then
    OUT=$(mktemp -d)
    trap 'rm -rf "$OUT"' EXIT
fi
mkdir -p "$OUT"

CTS=("example_ct:$DATA/totalseg-example-ct/example_ct.nii.gz"
     "aorta_crop:$DATA/totalseg-example-ct/ct_cropped_aorta_report.nii.gz"
     "dicom_series:$DATA/totalseg-example-ct/example_ct_dicom"
     "headsq_quarter:$DATA/vtk-headsq-quarter/quarter.nhdr"
     "ge_tilt:$DATA/dcmqa-ct-ge-tilt"
     "wrist_radius:$DATA/autoscoper-bvr/Models/rad_dcm_cropped.tif?spacing=0.39625,0.39625,0.625")

printf '| CT | film | threads | AP mu / raw | lateral mu / raw | oblique mu / raw | pole mu / raw | smallest |\n'
printf '|---|---|---|---|---|---|---|---|\n'
overall=""
for ct in "${CTS[@]}"; do
    name=${ct%%:*}
    spec=${ct#*:}
    if [ -n "$ONLY" ] && [[ ",$ONLY," != *",$name,"* ]]; then continue; fi
    for size in 256x256 512x512; do
        for threads in 1 2; do
            report="$OUT/${name}_${size}_${threads}.txt"
            if ! bash scripts/compare_plastimatch.sh --fluoromatch "$FM" --volume "$spec" --size "$size" \
                --threads "$threads" --repeat "$REPEAT" >"$report" 2>&1; then
                printf '| %s | %s | %s | skipped: %s |\n' "$name" "$size" "$threads" \
                    "$(grep -m1 -iE 'not mapped|error|refused' "$report" | cut -c1-90)"
                continue 2
            fi
            # Lines "view values ours plm ratio..."; ratio is the fifth field ("4.81x").
            row=$(awk '/^(AP|lateral|oblique|pole) +(mu|raw) / {
                           r[$1 "_" $2] = substr($5, 1, length($5) - 1)
                           if (min == "" || r[$1 "_" $2] + 0 < min + 0) min = r[$1 "_" $2] }
                       END { printf "%s / %s | %s / %s | %s / %s | %s / %s | %s",
                             r["AP_mu"], r["AP_raw"], r["lateral_mu"], r["lateral_raw"],
                             r["oblique_mu"], r["oblique_raw"], r["pole_mu"], r["pole_raw"], min }' \
                  "$report")
            printf '| %s | %s | %s | %s |\n' "$name" "$size" "$threads" "$row"
            low=${row##*| }
            if [ -z "$overall" ] || awk -v a="$low" -v b="$overall" 'BEGIN {exit !(a < b)}'; then
                overall=$low
            fi
        done
    done
done
echo
echo "smallest plastimatch / ours over all rows: ${overall:-none}"
echo "reports: $OUT (load average now: $(cut -d' ' -f1-3 /proc/loadavg))"
