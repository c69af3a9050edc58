# Sourced by the CLI tests on the JTML knee (shared data) with the executable as $1: sets FM, D (the
# data folder), OUT (a scratch folder removed at exit), fail, CAL, FEM and TIB. Without the data it
# exits 77 (skipped), or 1 under CI (the data must be there).
FM=$1
DATA=${FM_DATA_DIR:-$(dirname "${BASH_SOURCE[0]}")/../../../shared/data}
D="$DATA/jtml-kneel-tka-fluoro"
if [ ! -f "$D/fem.jts" ]; then
    [ "${CI:-}" = "true" ] && { echo "FAIL: shared data missing under CI"; exit 1; }
    echo "shared data not found: skipped"; exit 77
fi
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
CAL="$D/calibration.txt"
FEM="$D/KR_right_7_fem.stl"
TIB="$D/KR_right_6_tib.stl"
