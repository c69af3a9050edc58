#!/usr/bin/env bash
# Throughput of `fluoromatch evaluate` (registrations per second) against the number of MPI
# ranks on this machine, 1 thread per rank, and the parallel efficiency
# E(n) = throughput(n) / (n * throughput(1)). Also each rank's peak memory (max RSS) and the
# bytes every registration moves to rank 0. Figures in docs/distributed.md.
#   bash scripts/bench_distributed.sh [RANKS...]        # default: 1 2
#   FM=build/app/fluoromatch STARTS=2 METHODS=mc,cmaes bash scripts/bench_distributed.sh 1 2 4
set -euo pipefail
cd "$(dirname "$0")/.."
FM=${FM:-build/app/fluoromatch}
STARTS=${STARTS:-2}
METHODS=${METHODS:-mc,cmaes}
VOLUME=${VOLUME:-phantom:knee}
RANKS=("$@")
[ ${#RANKS[@]} -gt 0 ] || RANKS=(1 2)
FLAGS=()
if mpiexec --version 2>&1 | grep -q "Open MPI\|OpenRTE"; then
    FLAGS=(--oversubscribe --bind-to none --mca btl self,vader)
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    export OMPI_MCA_btl_vader_single_copy_mechanism=none
fi
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
echo "evaluate --volume $VOLUME --methods $METHODS --starts $STARTS --threads 1, $(nproc) cores"
printf "%5s %8s %10s %12s %10s %14s\n" ranks jobs "wall s" "reg/s" efficiency "max RSS/rank"
base=""
for n in "${RANKS[@]}"; do
    t0=$(date +%s.%N)
    mpiexec -n "$n" "${FLAGS[@]}" /usr/bin/time -f "rss %M" \
        "$FM" evaluate --volume "$VOLUME" --methods "$METHODS" --starts "$STARTS" --threads 1 \
        >"$OUT/out$n.txt" 2>"$OUT/err$n.txt" || { cat "$OUT/err$n.txt"; exit 1; }
    t1=$(date +%s.%N)
    jobs=$(sed -n 's/.*; \([0-9]*\) registrations, \([0-9]*\) bytes.*/\1/p' "$OUT/out$n.txt")
    bytes=$(sed -n 's/.*; \([0-9]*\) registrations, \([0-9]*\) bytes.*/\2/p' "$OUT/out$n.txt")
    rss=$(grep '^rss ' "$OUT/err$n.txt" | awk '{ if ($2 > m) m = $2 } END { printf "%.0f MiB", m / 1024 }')
    python3 - "$n" "$jobs" "$t0" "$t1" "$base" "$rss" <<'PY'
import sys
n, jobs, t0, t1, base, rss = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), sys.argv[5], sys.argv[6]
wall = t1 - t0
rate = jobs / wall
eff = rate / (n * float(base)) if base else 1.0
print(f"{n:5d} {jobs:8d} {wall:10.2f} {rate:12.3f} {eff:10.2f} {rss:>14}")
PY
    [ -n "$base" ] || base=$(python3 -c "print($jobs / ($t1 - $t0))")
done
echo "each registration moves $bytes bytes to rank 0 (its result record)"
