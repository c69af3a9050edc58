#!/usr/bin/env bash
# `fluoromatch simulate` end to end on the knee phantom (its femur flexing over the rest):
#  1. the trial it writes (trial.json, and trial.cfg for Autoscoper) is tracked by `track` from
#     the first frame's truth, and `compare` finds every frame within 0.5 mm and 0.5 deg of the
#     truth it wrote (the truth, the frames and the trial agree on every frame convention);
#     Raw detector intensities (--signal linear) make a trial that says "log, I0 50000" in both
#     files, and tracked with it every frame is within 0.25 mm and 0.25 deg;
#  2. the same seed gives the same bytes on 1 and 2 threads, another seed other frames;
#  3. refusals: camera placement options with --cameras, a volume not in HU, an unknown bone,
#     a motion it cannot read.
set -uo pipefail
FM=$1
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
# FM_SIMULATE_FRAMES: fewer frames for the sanitizer build (app/CMakeLists.txt), 5 deg apart
# as the 5 are.
N=${FM_SIMULATE_FRAMES:-5}
[ "$N" -ge 3 ] || fail "FM_SIMULATE_FRAMES=$N: at least 3 frames (one tracked from two before it)"
LAST=$(printf '%04d' $((N - 1))) BEFORE_LAST=$(printf '%04d' $((N - 2)))
sim() {  # sim OUT args...
    local out=$1; shift
    "$FM" simulate --volume phantom:knee --labels phantom:knee --bone femur --motion "rotate:axis=x,angle=0:$((5 * (N - 1)))" \
        --frames "$N" --size "${SIZE:-256x256}" --out "$out" "$@"
}

out=$(sim "$T/a" --threads 2 2>"$T/progress") || fail "simulate exited $?: $out"
# Its progress in a log (not a terminal): one line per frame, not one line of carriage returns.
[ "$(grep -c "^frame [0-9]* of $N$" "$T/progress")" -eq "$N" ] || { cat -A "$T/progress"; fail "progress: one line per frame"; }
for f in trial.json trial.cfg cam1.txt cam2.txt femur.tif femur_truth.tra femur_start.tra cam1/frame_$LAST.tif cam2/frame_0000.tif; do
    [ -s "$T/a/$f" ] || fail "$f not written: $(ls -R "$T/a")"
done
[ "$(wc -l < "$T/a/femur_truth.tra")" -eq "$N" ] || fail "the truth must have $N rows"
"$FM" radiograph "$T/a/cam1/frame_0002.tif" --out "$T/f.png" | grep -q "16-bit" || fail "frames are 16-bit TIFFs"
"$FM" track --trial "$T/a/trial.json" --bone femur --start "$T/a/femur_start.tra" --out "$T/a/tracked.tra" \
    >/dev/null 2>&1 || fail "track on the simulated trial failed"
out=$("$FM" compare --truth "$T/a/femur_truth.tra" --tra "$T/a/tracked.tra" --trial "$T/a/trial.json" --bone femur) ||
    fail "compare exited $?: $out"
grep -q "0.5 mm and 0.5 deg: 100.0 % ($N of $N)" <<<"$out" || fail "not every frame within 0.5 mm / 0.5 deg: $out"
# The same trial through Autoscoper's .cfg (its bone named by its TIFF stack's file name).
"$FM" track --trial "$T/a/trial.cfg" --bone femur --start "$T/a/femur_start.tra" --out "$T/a/tracked_cfg.tra" \
    >/dev/null 2>&1 || fail "track on the simulated trial.cfg failed"
out=$("$FM" compare --truth "$T/a/femur_truth.tra" --tra "$T/a/tracked_cfg.tra" --trial "$T/a/trial.cfg" --bone femur) ||
    fail "compare (cfg) exited $?: $out"
grep -q "0.5 mm and 0.5 deg: 100.0 % ($N of $N)" <<<"$out" || fail "trial.cfg: not every frame within 0.5 mm / 0.5 deg: $out"

# Raw detector intensities: the trial says how to prepare them, track says it took that, and
# every frame is within 0.25 mm / 0.25 deg (the worst centre and rotation errors of compare).
SIZE=512x512 sim "$T/lin" --threads 2 --signal linear >/dev/null 2>&1 || fail "simulate --signal linear failed"
grep -q '"values": "log"' "$T/lin/trial.json" || fail "trial.json does not say log: $(cat "$T/lin/trial.json")"
[ "$(grep -c '^RadiographPreparation log i0=50000$' "$T/lin/trial.cfg")" -eq 2 ] || fail "trial.cfg: $(cat "$T/lin/trial.cfg")"
out=$("$FM" track --trial "$T/lin/trial.cfg" --bone femur --start "$T/lin/femur_start.tra" --out "$T/lin/t.tra" 2>/dev/null) ||
    fail "track (linear) failed: $out"
grep -q "^cam2      frames prepared as log, -ln(I / I0), I0 = 50000  (the trial's)" <<<"$out" || fail "track did not say the trial's log: $out"
out=$("$FM" compare --truth "$T/lin/femur_truth.tra" --tra "$T/lin/t.tra" --trial "$T/lin/trial.json" --bone femur) ||
    fail "compare (linear) exited $?: $out"
awk '/^  (centre|rotation) / && $5 + 0 > 0.25 {exit 1}' <<<"$out" ||
    fail "raw intensities, log-prepared: a frame beyond 0.25 mm / 0.25 deg: $out"
[ "$(grep -c -E '^  (centre|rotation) ' <<<"$out")" -eq 2 ] || fail "compare's table changed: $out"

sim "$T/b" --threads 1 >/dev/null 2>&1 || fail "1 thread"
sim "$T/c" --threads 2 --seed 2 >/dev/null 2>&1 || fail "seed 2"
for f in cam1/frame_$BEFORE_LAST.tif cam2/frame_0001.tif femur_truth.tra; do
    cmp -s "$T/a/$f" "$T/b/$f" || fail "$f differs between 2 threads and 1"
done
cmp -s "$T/a/cam1/frame_$BEFORE_LAST.tif" "$T/c/cam1/frame_$BEFORE_LAST.tif" && fail "another seed gave the same frame"

expect_error() {  # expect_error TEXT args...
    local text=$1; shift
    if "$FM" simulate "$@" >"$T/out" 2>&1; then fail "'simulate $*' succeeded"; fi
    grep -q -- "$text" "$T/out" || { cat "$T/out"; fail "'simulate $*' did not say '$text'"; }
}
common=(--labels phantom:knee --frames 2 --out "$T/x")
expect_error "--separation places cameras" --volume phantom:knee "${common[@]}" --bone femur --motion "rotate:axis=x,angle=0:2" --cameras "$T/a/cam1.txt" --separation 50
expect_error "--azimuth places cameras" --volume phantom:knee "${common[@]}" --bone femur --motion "rotate:axis=x,angle=0:2" --cameras "$T/a/cam1.txt" --azimuth -40
expect_error "--extend-scan" --volume phantom:knee "${common[@]}" --bone femur --motion "rotate:axis=x,angle=0:2" --extend-scan -5
expect_error "needs a CT in HU" --volume phantom:sphere --labels components --bone "component 1" --frames 2 --out "$T/x" --motion "rotate:axis=x,angle=0:2"
expect_error "humerus" --volume phantom:knee "${common[@]}" --bone humerus --motion "rotate:axis=x,angle=0:2"
expect_error "--motion" --volume phantom:knee "${common[@]}" --bone femur --motion "spin:fast"
echo "simulate: ok"
