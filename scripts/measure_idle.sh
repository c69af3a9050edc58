#!/usr/bin/env bash
# Idle CPU of the app's window (issue 15: an idle app uses no CPU). Starts `fluoromatch app
# ARGS` in a real GLFW window on a virtual X server, lets it load and settle, then reads the
# process's CPU time (user + sys of all its threads, /proc/PID/stat) over a quiet interval, and
# over one in which the mouse moves across the window every 0.2 s (the app must wake and draw).
#   bash scripts/measure_idle.sh [--settle S] [--seconds S] [-- app options...]
# Needs Xvfb and xdotool (scripts/setup installs both). Prints CPU as % of one core.
set -euo pipefail
cd "$(dirname "$0")/.."
settle=8
seconds=10
while [ $# -gt 0 ]; do
    case "$1" in
        --settle) settle=$2; shift 2 ;;
        --seconds) seconds=$2; shift 2 ;;
        --) shift; break ;;
        *) echo "measure_idle: unknown option $1" >&2; exit 2 ;;
    esac
done
exe=${FLUOROMATCH:-build/app/fluoromatch}
[ -x "$exe" ] || { echo "measure_idle: $exe not built (bash scripts/setup)" >&2; exit 1; }
display=:$(( 90 + RANDOM % 100 ))
Xvfb "$display" -screen 0 1280x800x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
log=$(mktemp)
cleanup() { kill "${app:-}" "$xvfb" 2>/dev/null || true; rm -f "$log"; }
trap cleanup EXIT
sleep 1
DISPLAY=$display "$exe" app --require-window "$@" >"$log" 2>&1 &
app=$!
sleep "$settle"
kill -0 "$app" 2>/dev/null || { cat "$log"; echo "measure_idle: the app exited" >&2; exit 1; }
ticks() { awk '{print $14 + $15}' "/proc/$app/stat"; }
hz=$(getconf CLK_TCK)
percent() { awk -v a="$1" -v b="$2" -v s="$3" -v hz="$hz" 'BEGIN { printf "%.1f", 100 * (b - a) / hz / s }'; }

t0=$(ticks); sleep "$seconds"; t1=$(ticks)
echo "idle:        $(percent "$t0" "$t1" "$seconds") % of a core over ${seconds} s (no input)"

t0=$(ticks)
end=$(( $(date +%s) + seconds ))
i=0
while [ "$(date +%s)" -lt "$end" ]; do
    DISPLAY=$display xdotool mousemove $(( 200 + (i % 40) * 20 )) $(( 200 + (i % 7) * 30 )) >/dev/null 2>&1 || true
    i=$((i + 1))
    sleep 0.2
done
t1=$(ticks)
echo "mouse moves: $(percent "$t0" "$t1" "$seconds") % of a core over ${seconds} s (${i} moves, one every 0.2 s)"
grep -m1 "^window:" "$log" || true
