# Sourced by the CLI tests on the JTML knee (shared data) with the executable as $1: sets FM, D (the
# data folder), OUT (a scratch folder removed at exit), fail, CAL, FEM and TIB. Without the data it
# exits 77 (skipped), or 1 under CI (the data must be there).
FM=$1
. "$(dirname "${BASH_SOURCE[0]}")/require_shared_data.sh"
require_shared_data jtml-kneel-tka-fluoro/fem.jts
D="$DATA/jtml-kneel-tka-fluoro"
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
CAL="$D/calibration.txt"
FEM="$D/KR_right_7_fem.stl"
TIB="$D/KR_right_6_tib.stl"
