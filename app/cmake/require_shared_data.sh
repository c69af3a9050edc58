# Sourced by the CLI tests that read ../shared/data: `require_shared_data PATH...` (paths below
# the data folder, $DATA) returns when all exist; else exits 77 (skipped), or 1 under CI=true
# (there the data must be there). Sets DATA from FM_DATA_DIR (default ../shared/data beside the
# checkout).
DATA=${FM_DATA_DIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)/shared/data}
require_shared_data() {
    local p
    for p in "$@"; do
        if [ ! -e "$DATA/$p" ]; then
            [ "${CI:-}" = "true" ] && { echo "FAIL: shared data missing under CI: $DATA/$p"; exit 1; }
            echo "shared data not found ($DATA/$p): skipped"; exit 77
        fi
    done
}
