#!/usr/bin/env bash
# `register` on the knee phantom from a start inside CMA-ES's stated capture range (7,-6,5,88,52,7
# towards 0,0,0,80,60,0: 13.1 mm mTRE): one search missed with seed 7 of 12 (8.2 mm). Confirmed
# by searches from independent starts (the default), every seed ends within 1 mm and says ok;
# with --runs 1 seed 7 still misses and its verdict is not ok (the similarity against a perfect
# match sees it). docs/search.md, "Confirmed searches and verdicts".
set -uo pipefail
FM=$1
fail() { echo "FAIL: $*"; exit 1; }
run() {  # run SEED [options]: prints "mTRE verdict"
    local seed=$1; shift
    local out
    out=$("$FM" register --start 7,-6,5,88,52,7 --reference-pose 0,0,0,80,60,0 --seed "$seed" --threads 2 "$@" 2>&1) ||
        fail "seed $seed exited non-zero: $out"
    local mtre verdict
    mtre=$(sed -n 's/^mTRE .*-> final \([0-9.]*\) mm.*/\1/p' <<<"$out")
    verdict=$(sed -n 's/^verdict     \([a-z]*\):.*/\1/p' <<<"$out")
    [ -n "$mtre" ] && [ -n "$verdict" ] || fail "seed $seed: no mTRE or verdict line: $out"
    echo "$mtre $verdict"
}
# FM_CONFIRMED_SEEDS: fewer seeds for the sanitizer build (app/CMakeLists.txt).
seeds=${FM_CONFIRMED_SEEDS:-1 2 3 4 5 6 7 8 9 10 11 12}
count=0
for seed in $seeds; do
    count=$((count + 1))
    read -r mtre verdict < <(run "$seed")
    awk -v m="$mtre" 'BEGIN { exit !(m < 1.0) }' || fail "seed $seed: final mTRE $mtre mm"
    [ "$verdict" = ok ] || fail "seed $seed: within $mtre mm but the verdict is $verdict"
done
read -r mtre verdict < <(run 7 --runs 1)
awk -v m="$mtre" 'BEGIN { exit !(m > 1.0) }' || fail "seed 7 alone no longer misses ($mtre mm): the test lost its case"
[ "$verdict" != ok ] || fail "seed 7 alone missed by $mtre mm and said ok"
echo "register confirmed: $count of $count seeds within 1 mm and ok; seed 7 alone $mtre mm, $verdict"
