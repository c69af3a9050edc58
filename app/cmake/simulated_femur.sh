# Sourced by the femur proofs (cli_simulate_femur_test.sh, cli_find_femur_test.sh): shared data
# required (skips without it, fails under CI=true), a temporary folder $T, fail(), and
# simulate_femur DIR [simulate options...]: example_ct's right femur (a stub cut by the scan's end,
# 3 mm voxels) flexing 0-30 deg over the rest of the CT in 10 frames, two cameras 80 deg apart.
SRC=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
. "$(dirname "${BASH_SOURCE[0]}")/require_shared_data.sh"
require_shared_data totalseg-example-ct/example_ct.nii.gz totalseg-example-ct/example_seg_fast_force_split.nii.gz
D="$DATA/totalseg-example-ct"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
simulate_femur() {
    local dir=$1; shift
    local out
    out=$("$FM" simulate --volume "$D/example_ct.nii.gz" --labels "$D/example_seg_fast_force_split.nii.gz" \
        --label-table "$SRC/data/totalseg_bones.json" --bone femur_right --motion "rotate:axis=x,angle=0:30" \
        --frames 10 --out "$dir" "$@" 2>&1) || fail "simulate exited $?: $out"
}
