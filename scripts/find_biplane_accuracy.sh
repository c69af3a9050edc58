#!/usr/bin/env bash
# The biplane pose from nothing against the size of the search space (docs/find.md, "Biplane"):
# example_ct's right femur flexing 0-30 deg in 20 frames, two cameras 80 deg apart turned -40 deg,
# 10^4 photons (the proof of app/cmake/cli_find_femur_test.sh, simulated once), then for each
# search space given (default: tilt 20, 35, 50, 90 = every orientation, and tilt 90 with roll +-90)
# and each of frames 0, 6, 13, 19: `fluoromatch track --frames K:K --find-space SPACE` with no
# keyframe, so the bone is found in frame K in both cameras at once and that frame registered from
# it. Per run: the find's orientations, its verdict and ratio (the best other basin's score over
# the best's), the time per stage (scan, glance + refine, finish; both passes of a find scanned
# twice summed), and the error of the registered frame K against the truth (`compare`: centre mm,
# rotation deg); per space, how many runs are ok, doubtful (track refuses those: no pose to score)
# or lost, how many within 0.5 mm / 0.5 deg, and how many ok but not within it (a wrong answer
# called ok: the failure that matters). Release build; 2 cores take ~1 minute per run.
#   FM_DATA_DIR=/work/shared/data bash scripts/find_biplane_accuracy.sh ["tilt=35" "tilt=90,roll=90" ...]
#   FRAMES="0 13" ... to choose the frames; FM=path/to/fluoromatch; ROWS=file.tsv keeps the rows,
#   LOGS=folder each run's track output.
set -euo pipefail
cd "$(dirname "$0")/.."
FM=${FM:-build/app/fluoromatch}
D=${FM_DATA_DIR:-../shared/data}/totalseg-example-ct
read -r -a frames <<<"${FRAMES:-0 6 13 19}"
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
ROWS=${ROWS:-$OUT/rows.tsv}
: >"$ROWS"
spaces=("$@")
[ ${#spaces[@]} -gt 0 ] || spaces=("tilt=20" "tilt=35" "tilt=50" "tilt=90" "tilt=90,roll=90")

S=$OUT/sim
"$FM" simulate --volume "$D/example_ct.nii.gz" --labels "$D/example_seg_fast_force_split.nii.gz" \
    --label-table data/totalseg_bones.json --bone femur_right --motion "rotate:axis=x,angle=0:30" \
    --frames 20 --photons 10000 --azimuth -40 --out "$S" >"$OUT/simulate.log" 2>&1 ||
    { cat "$OUT/simulate.log" >&2; exit 1; }
# A keyframe in the trial would be used instead of a find: take any out (simulate writes none today).
/usr/bin/python3 - "$S/trial.json" <<'PY'
import json, sys
path = sys.argv[1]
trial = json.load(open(path))
if trial.pop("keyframes", None) is not None:
    json.dump(trial, open(path, "w"), indent=2)
    print("removed the keyframes of " + path, file=sys.stderr)
PY

printf "%-16s %6s %5s %9s %9s %-9s %-7s %7s %8s %8s %-8s %7s\n" space orient frame centre_mm rot_deg \
    verdict ratio scan_s refine_s finish_s tracked wall_s
for space in "${spaces[@]}"; do
    for k in "${frames[@]}"; do
        rm -f "$OUT/x.tra" "$OUT/cmp.csv"
        start=$(date +%s.%N)
        rc=0
        "$FM" track --trial "$S/trial.json" --bone femur_right --frames "$k:$k" --find-space "$space" \
            --out "$OUT/x.tra" >"$OUT/track.log" 2>&1 || rc=$?
        wall=$(/usr/bin/python3 -c "import sys; print('%.1f' % (float(sys.argv[2]) - float(sys.argv[1])))" \
            "$start" "$(date +%s.%N)")
        [ -z "${LOGS:-}" ] || { mkdir -p "$LOGS" && cp "$OUT/track.log" "$LOGS/track_${space//[=,:]/_}_$k.log"; }
        if [ "$rc" -eq 0 ] && [ -f "$OUT/x.tra" ]; then
            "$FM" compare --truth "$S/femur_right_truth.tra" --tra "$OUT/x.tra" --trial "$S/trial.json" \
                --bone femur_right --csv "$OUT/cmp.csv" >"$OUT/compare.log" 2>&1 || true
        fi
        /usr/bin/python3 - "$OUT/track.log" "$OUT/cmp.csv" "$space" "$k" "$wall" "$rc" "$ROWS" <<'PY'
import csv, math, os, re, sys
log, cmp_csv, space, frame, wall, rc, rows = sys.argv[1:8]
text = open(log).read()
def first(pattern, default="-"):
    m = re.search(pattern, text, re.M)
    return m.group(1) if m else default
orient = first(r"^ +(\d+) orientations?, scan at")
verdict = first(r"^ +(ok|doubtful|lost): ", "none")
ratio = first(r"another basin scores ([0-9.]+) of it")
if ratio == "-":
    ratio = first(r"all (\d+) finalists ended at it")
    ratio = "all" + ratio if ratio != "-" else "-"
def seconds(*names):  # summed over the names and over both passes of a find scanned twice
    found = [float(t) for n in names for t in re.findall(r"^ +%s +([0-9.]+) s" % n, text, re.M)]
    return "%.2f" % sum(found) if found else "-"
stage = {"scan": seconds("scan"), "refine": seconds("glance", "refine"), "finish": seconds("finish")}
tracked = first(r"^femur_right: verdict (\d+ ok, \d+ doubtful, \d+ lost)")
tracked = ("ok" if tracked.startswith("1 ok") else "doubtful" if ", 1 doubtful" in tracked
           else "lost" if tracked.endswith("1 lost") else tracked)
centre = rot = "-"
if os.path.exists(cmp_csv):
    for r in csv.DictReader(open(cmp_csv)):
        if r["frame"] == frame and r["centre_mm"] not in ("", "nan"):
            centre, rot = "%.3f" % float(r["centre_mm"]), "%.3f" % float(r["rotation_deg"])
fields = [space, orient, frame, centre, rot, verdict, ratio, stage["scan"], stage["refine"], stage["finish"],
          tracked, wall]
print("%-16s %6s %5s %9s %9s %-9s %-7s %7s %8s %8s %-8s %7s" % tuple(fields))
if rc != "0":
    err = [l.split("error: ", 1)[1] for l in text.splitlines() if "error: " in l]
    print("    track exited %s%s" % (rc, (": " + err[-1][:110]) if err else ""))
with open(rows, "a") as f:
    f.write("\t".join(fields) + "\n")
PY
    done
done

echo
echo "per space: runs, verdicts, within 0.5 mm / 0.5 deg (of those with a pose), ok but not within it"
/usr/bin/python3 - "$ROWS" <<'PY'
import sys
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1]) if l.strip()]
spaces = list(dict.fromkeys(r[0] for r in rows))
for s in spaces:
    rs = [r for r in rows if r[0] == s]
    count = lambda v: sum(1 for r in rs if r[5] == v)
    scored = [r for r in rs if r[3] != "-"]
    met = [r for r in scored if float(r[3]) <= 0.5 and float(r[4]) <= 0.5]
    wrong_ok = [r for r in rs if r[5] == "ok" and r not in met]
    def mean(i):
        v = [float(r[i]) for r in rs if r[i] != "-"]
        return "%.1f" % (sum(v) / len(v)) if v else "-"
    print("%-16s runs %d: ok %d, doubtful %d, lost %d; met %d of %d scored; ok but not met %d%s; "
          "mean scan %s s, refine %s s, finish %s s" % (
              s, len(rs), count("ok"), count("doubtful"), count("lost"), len(met), len(scored), len(wrong_ok),
              (" (frames " + ", ".join(r[2] for r in wrong_ok) + ")") if wrong_ok else "", mean(7), mean(8), mean(9)))
PY
