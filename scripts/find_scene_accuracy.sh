#!/usr/bin/env bash
# The 2011 scene's pose from nothing against the size of the search space (docs/find.md, "The
# 2011 scene"): the knee phantom's hard reference draws (the app's drawReferencePose, seeds 1..N,
# as the proof test ViewFinderProof.KneePhantomHardDraws draws them), each registered by
# `fluoromatch register --reference-pose POSE --find-space SPACE --runs 1` with no start; per draw
# the final mTRE, the verdict and the finder's time, then the count within 1 mm.
#   bash scripts/find_scene_accuracy.sh [SPACE] [DRAWS]    (default: the default space, 20 draws)
set -euo pipefail
cd "$(dirname "$0")/.."
FM=${FM:-build/app/fluoromatch}
SPACE=${1:-elevation=45,rotation=30,offset=40}
DRAWS=${2:-20}
# The proof test prints each draw it finds ("knee phantom draw K (view) truth POSE found ...").
poses=$(FM_VIEW_DRAWS="$DRAWS" build/tests/fm_test_find --gtest_filter=ViewFinderProof.KneePhantomHardDraws |
    sed -n 's/^knee phantom draw .* truth \([^ ]*\) found .*/\1/p')
[ -n "$poses" ] || { echo "no draws printed by fm_test_find" >&2; exit 1; }
met=0; n=0
for pose in $poses; do
    out=$("$FM" register --reference-pose "$pose" --find-space "$SPACE" --runs 1 --threads 2 2>/dev/null)
    mtre=$(sed -n 's/^mTRE .* -> final \([0-9.]*\) mm.*/\1/p' <<<"$out")
    found=$(sed -n 's/^found at .*(\([0-9.]*\) s)$/\1/p' <<<"$out")
    verdict=$(sed -n 's/^verdict     \([a-z]*\).*/\1/p' <<<"$out")
    scan=$(sed -n 's/^found       scan *\([0-9.]*\) s.*/\1/p' <<<"$out")
    printf "%-36s mTRE %7s mm  %-9s found %5s s (scan %s s)\n" "$pose" "$mtre" "$verdict" "$found" "$scan"
    n=$((n + 1))
    met=$((met + $(python3 -c "print(1 if $mtre < 1.0 else 0)")))
done
echo "$SPACE: $met of $n within 1 mm"
