# Sourced by the CLI test scripts (after they define fail and FM): `refuse WHAT PATTERN args...` runs
# `$FM register args...` and fails the script unless it exits non-zero, its message says PATTERN,
# and it printed no line matching $REFUSED_BEFORE (the line a search that ran would print: the
# refusal must come before any work).
refuse() {
    local what=$1 pattern=$2; shift 2
    msg=$("$FM" register "$@" 2>&1) && fail "$what accepted"
    grep -q -- "$pattern" <<<"$msg" || fail "$what: message does not say '$pattern': $msg"
    grep -q "$REFUSED_BEFORE" <<<"$msg" && fail "$what: refused only after the search"
    return 0
}
