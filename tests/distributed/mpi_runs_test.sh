#!/usr/bin/env bash
# Distributed runs on this machine over loopback (shared memory, no NIC), 1, 2 and 3 ranks:
#  1. the job runner's GoogleTests pass under mpirun -np 2 and -np 3 (records reach rank 0 in
#     job order, job j on rank j % size, failures named with their rank, others finish);
#  2. `fluoromatch evaluate --csv` gives byte-identical CSVs without mpirun and with 1, 2 and 3
#     ranks, except the columns of measured times (header contains "second" or "time", or ends
#     in "_ms"), which are dropped before comparing;
#  3. `fluoromatch drr --poses` writes byte-identical files (PNG and exact values per view)
#     without mpirun and with 1, 2 and 3 ranks;
#  4. a view that cannot be written fails alone: the others are written, the run exits
#     non-zero and names the job;
#  5. `fluoromatch track` (the wrist trial at 110 pixels, 2 bones x 2 keyframe segments = 4
#     jobs) writes byte-identical .tra files and CSVs (without the time column) without mpirun
#     and on 1, 2 and 3 ranks; a bone whose .tra cannot be written fails its jobs alone.
# Usage: mpi_runs_test.sh MPI_FOUND MPIEXEC TEST_BINARY FLUOROMATCH LSAN_SUPPRESSIONS
# FM_MPI_RANKS: the rank counts (default "1 2 3"; the sanitizer build runs "3":
# tests/distributed/extra.cmake); the job runner's tests run on those above 1.
# Skips (77) only when the build has no MPI, and never under CI=true (CI installs MPI).
set -uo pipefail
MPI_FOUND=$1 MPIEXEC=$2 TESTS=$3 FM=$4 SUPP=$5
fail() { echo "FAIL: $*"; exit 1; }
RANKS=${FM_MPI_RANKS:-1 2 3}
if [ "$MPI_FOUND" != "ON" ]; then
    [ "${CI:-}" = "true" ] && fail "built without MPI under CI=true (scripts/setup installs libopenmpi-dev)"
    echo "SKIP: fluoromatch was built without MPI (install libopenmpi-dev and re-run cmake)"
    exit 77
fi
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

# Launcher flags. Open MPI: allow root (CI), more ranks than cores, no pinning (each rank runs
# its own threads), shared memory without the CMA single-copy path (refused in containers),
# and only the self and shared-memory transports (loopback: no traffic leaves the machine).
FLAGS=()
if "$MPIEXEC" --version 2>&1 | grep -q "Open MPI\|OpenRTE"; then
    FLAGS=(--oversubscribe --bind-to none --mca btl self,vader)
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    export OMPI_MCA_btl_vader_single_copy_mechanism=none
fi
# Under AddressSanitizer: Open MPI's own allocations at exit are not ours (suppressions scoped to
# its libraries; the full unwinder is needed to see through its plugins). See docs/distributed.md.
# Only for runs under mpirun: a run without it never starts MPI, and the full unwinder on every
# allocation is most of the leak check's cost.
MPI_LSAN="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$SUPP:fast_unwind_on_malloc=0"
run() { local n=$1; shift; LSAN_OPTIONS=$MPI_LSAN "$MPIEXEC" -n "$n" "${FLAGS[@]}" "$@"; }

# 1. The runner's tests on the rank counts above 1 (each rank runs the whole suite; all must pass).
for n in $RANKS; do
    [ "$n" -gt 1 ] || continue
    run "$n" "$TESTS" --gtest_brief=1 >"$OUT/gtest$n.log" 2>&1 || {
        cat "$OUT/gtest$n.log"; fail "the job runner's tests failed on $n ranks"; }
    passed=$(grep -c "PASSED" "$OUT/gtest$n.log")
    [ "$passed" -eq "$n" ] || { cat "$OUT/gtest$n.log"; fail "$passed of $n ranks passed"; }
    echo "job runner tests: pass on every one of $n ranks"
done

# 2. evaluate: 2 methods x 4 bins x 1 start = 8 registrations, small budgets, 1 thread a rank.
EVAL=(evaluate --methods mc,cmaes --starts 1 --budget 60 --polish-budget 20 --levels 4,2 --threads 1)
"$FM" "${EVAL[@]}" --csv "$OUT/plain.csv" >"$OUT/plain.txt" 2>&1 || {
    cat "$OUT/plain.txt"; fail "evaluate without mpirun exited $?"; }
grep -q "processes  1 (single process)" "$OUT/plain.txt" || fail "a plain run did not say it ran on one process"
# Columns to compare: every one whose header does not name a measured time.
keep=$(head -1 "$OUT/plain.csv" | tr ',' '\n' | grep -n -v -E 'second|time|_ms$' | cut -d: -f1 | paste -sd,)
dropped=$(head -1 "$OUT/plain.csv" | tr ',' '\n' | grep -E 'second|time|_ms$' | paste -sd' ')
[ -n "$dropped" ] || fail "no time column found to drop: the header changed?"
[ "$(wc -l <"$OUT/plain.csv")" -eq 9 ] || fail "expected 8 rows and a header in the CSV"
cut -d, -f"$keep" "$OUT/plain.csv" >"$OUT/plain.cut"
for n in $RANKS; do
    run "$n" "$FM" "${EVAL[@]}" --csv "$OUT/np$n.csv" >"$OUT/np$n.txt" 2>&1 || {
        cat "$OUT/np$n.txt"; fail "evaluate on $n ranks exited $?"; }
    grep -q "processes  $n (MPI)" "$OUT/np$n.txt" || { cat "$OUT/np$n.txt"; fail "evaluate did not run on $n MPI ranks"; }
    cut -d, -f"$keep" "$OUT/np$n.csv" >"$OUT/np$n.cut"
    cmp "$OUT/plain.cut" "$OUT/np$n.cut" || {
        diff "$OUT/plain.cut" "$OUT/np$n.cut"; fail "evaluate's CSV on $n ranks differs from one process"; }
    # Rank 0 alone prints the tables: one summary, not n.
    [ "$(grep -c '^method  capture range' "$OUT/np$n.txt")" -eq 1 ] || fail "the summary was printed more than once on $n ranks"
    echo "evaluate on $n ranks: CSV identical to one process (apart from: $dropped)"
done

# 3. Batch DRRs (drr --poses): 5 views, PNG and exact values per view, byte-identical files
#    without mpirun and on 1, 2 and 3 ranks.
printf '0 0 0 0 0 0\n5 0 0 30 0 0\n# a comment\n0 -5 10 -40 10 5\n0 0 0 90 -20 0\n3 3 3 170 5 -10\n' >"$OUT/views.txt"
DRR=(drr --poses "$OUT/views.txt" --size 48x40 --threads 1)
mkdir -p "$OUT/drr-plain"
"$FM" "${DRR[@]}" --out "$OUT/drr-plain/v.png" --raw "$OUT/drr-plain/v.mha" >"$OUT/drr-plain.txt" 2>&1 || {
    cat "$OUT/drr-plain.txt"; fail "drr --poses without mpirun exited $?"; }
[ "$(ls "$OUT/drr-plain" | wc -l)" -eq 10 ] || { ls "$OUT/drr-plain"; fail "expected 5 PNGs and 5 .mha files"; }
for n in $RANKS; do
    mkdir -p "$OUT/drr-np$n"
    run "$n" "$FM" "${DRR[@]}" --out "$OUT/drr-np$n/v.png" --raw "$OUT/drr-np$n/v.mha" >"$OUT/drr-np$n.txt" 2>&1 || {
        cat "$OUT/drr-np$n.txt"; fail "drr --poses on $n ranks exited $?"; }
    grep -q "on $n process.* (MPI)" "$OUT/drr-np$n.txt" || { cat "$OUT/drr-np$n.txt"; fail "drr did not run on $n MPI ranks"; }
    diff -r "$OUT/drr-plain" "$OUT/drr-np$n" || fail "batch DRRs on $n ranks differ from one process"
    [ "$(grep -c '^wrote ' "$OUT/drr-np$n.txt")" -eq 5 ] || fail "rank 0 should report 5 views once on $n ranks"
    echo "drr --poses on $n ranks: 10 files identical to one process"
done

# 4. A job that fails: view 2's PNG cannot be written (a folder has its name). The other views
#    are written, the run exits 1 and names job 2.
mkdir -p "$OUT/drr-fail/v_002.png"
run 3 "$FM" "${DRR[@]}" --out "$OUT/drr-fail/v.png" >"$OUT/drr-fail.txt" 2>&1
rc=$?
cat "$OUT/drr-fail.txt"
[ $rc -ne 0 ] || fail "a run with a failed view exited 0"
grep -q "1 of 5 views failed.*job 2 (rank 0)" "$OUT/drr-fail.txt" || fail "the failed job is not named"
for v in 000 001 003 004; do [ -s "$OUT/drr-fail/v_$v.png" ] || fail "view $v was not written"; done
echo "a failed view: the others written, exit $rc naming job 2"

# 5. track: radius and ulna through the wrist trial's 3 frames from the trial's keyframes at
#    frames 0 and 1 (segments {0} and {1, 2}: 4 jobs), rendered at 110 pixels (RenderResolution)
#    to stay short.
SRC=$(cd "$(dirname "$0")/../.." && pwd)
WRIST=${FM_DATA_DIR:-$SRC/../shared/data}/autoscoper-bvr
if [ ! -d "$WRIST" ]; then
    [ "${CI:-}" = "true" ] && fail "$WRIST missing under CI"
    echo "track: skipped ($WRIST not found)"; echo "PASS"; exit 0
fi
sed -e "s#\.\./\.\./\.\./shared/data/autoscoper-bvr#$WRIST#g" \
    -e 's#"render_resolution": \[512, 512\]#"render_resolution": [110, 110]#' \
    "$SRC/data/trials/wrist.json" >"$OUT/wrist110.json"
grep -q '"render_resolution": \[110, 110\]' "$OUT/wrist110.json" || fail "could not make the 110-pixel trial"
TRACK=(track --trial "$OUT/wrist110.json" --bone radius --bone ulna --threads 1)
mkdir -p "$OUT/track-plain"
"$FM" "${TRACK[@]}" --out "$OUT/track-plain/t.tra" --csv "$OUT/track-plain/t.csv" >"$OUT/track-plain.txt" 2>&1 || {
    cat "$OUT/track-plain.txt"; fail "track without mpirun exited $?"; }
grep -q "jobs      4 (bone x keyframe segment) on 1 process" "$OUT/track-plain.txt" || {
    cat "$OUT/track-plain.txt"; fail "track did not make 4 jobs"; }
[ "$(wc -l <"$OUT/track-plain/t.csv")" -eq 7 ] || fail "expected 6 frame rows and a header in track's CSV"
tkeep=$(head -1 "$OUT/track-plain/t.csv" | tr ',' '\n' | grep -n -v -E 'second|time|_ms$' | cut -d: -f1 | paste -sd,)
head -1 "$OUT/track-plain/t.csv" | tr ',' '\n' | grep -q -x time_ms || fail "track's CSV has no time_ms column to drop"
for n in $RANKS; do
    d=$OUT/track-np$n; mkdir -p "$d"
    run "$n" "$FM" "${TRACK[@]}" --out "$d/t.tra" --csv "$d/t.csv" >"$d.txt" 2>&1 || {
        cat "$d.txt"; fail "track on $n ranks exited $?"; }
    grep -q "on $n process.* (MPI)" "$d.txt" || { cat "$d.txt"; fail "track did not run on $n MPI ranks"; }
    for b in radius ulna; do
        cmp "$OUT/track-plain/t_$b.tra" "$d/t_$b.tra" || fail "track's $b .tra on $n ranks differs from one process"
    done
    cmp <(cut -d, -f"$tkeep" "$OUT/track-plain/t.csv") <(cut -d, -f"$tkeep" "$d/t.csv") || {
        diff "$OUT/track-plain/t.csv" "$d/t.csv"; fail "track's CSV on $n ranks differs (apart from time_ms)"; }
    echo "track on $n ranks: 2 .tra files and the CSV (apart from time_ms) identical to one process"
done
# The ulna's .tra cannot be written (a folder has its name): every output is checked before
# any work (issue 35), so the run is refused on every rank at once, naming the file, and nothing
# is tracked or written. (Jobs that fail mid-run are named as the drr case above shows.)
mkdir -p "$OUT/track-fail/t_ulna.tra"
run 3 "$FM" "${TRACK[@]}" --out "$OUT/track-fail/t.tra" >"$OUT/track-fail.txt" 2>&1
rc=$?
[ $rc -ne 0 ] || { cat "$OUT/track-fail.txt"; fail "a track run with an unwritable output exited 0"; }
grep -q "t_ulna.tra.*is a folder" "$OUT/track-fail.txt" || {
    cat "$OUT/track-fail.txt"; fail "track's unwritable output is not named"; }
[ ! -e "$OUT/track-fail/t_radius.tra" ] || fail "a refused run tracked the radius"
echo "track with an unwritable output: refused before any work, exit $rc"
echo "PASS"
