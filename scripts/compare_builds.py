#!/usr/bin/env python3
"""Time two fluoromatch executables on the workloads the speed issues name, alternating runs
(this machine is shared and noisy: only runs side by side in time compare), and print each
run's figures and the medians.

    python3 scripts/compare_builds.py OLD_EXE NEW_EXE [--runs 3] [--data ../shared/data]
                                      [--only track,jtml,knee]

Workloads (all with --threads 2):
  track  the wrist trial, radius then ulna, 512 x 512 per view: seconds per frame (CSV time_ms)
  jtml   both JTML implants in frame 1, side by side: the registration's total time
  knee   `evaluate` on the knee phantom, every method, 3 starts per bin: median time/reg
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile


def run(cmd, cwd):
    out = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"failed ({out.returncode}): {' '.join(cmd)}\n{out.stderr}")
    return out.stdout


def track(exe, repo, data, work):
    csv = os.path.join(work, "track.csv")
    run([exe, "track", "--trial", os.path.join(repo, "data/trials/wrist.json"), "--bone", "radius",
         "--bone", "ulna", "--threads", "2", "--out", os.path.join(work, "track.tra"), "--csv", csv], work)
    rows = [line.split(",") for line in open(csv).read().splitlines()[1:]]
    return {f"{bone} s/frame": [float(r[7]) / 1000.0 for r in rows if r[1] == bone]
            for bone in ("radius", "ulna")}


def jtml(exe, repo, data, work):
    d = os.path.join(data, "jtml-kneel-tka-fluoro")
    out = run([exe, "register", "--reference", f"{d}/AT_K1_V1_0170.tif", "--camera", f"{d}/calibration.txt",
               "--model", f"{d}/KR_right_7_fem.stl", "--model", f"{d}/KR_right_6_tib.stl", "--invert",
               "--start", f"{d}/fem.jts", "--start", f"{d}/tib.jts", "--frame", "1", "--threads", "2"], work)
    total = re.search(r"total time\s+([0-9.]+) s", out)
    return {"jtml both implants s": [float(total.group(1))]}


def knee(exe, repo, data, work):
    out = run([exe, "evaluate", "--starts", "3", "--seed", "1", "--threads", "2"], work)
    figures = {}
    for m in re.finditer(r"^(mc|pso|bees|cmaes)\s+\d+ mm\s+(\d+)%\s+([0-9.]+) s", out, re.M):
        figures[f"knee {m.group(1)} s/reg ({m.group(2)} %)"] = [float(m.group(3))]
    return figures


WORKLOADS = {"track": track, "jtml": jtml, "knee": knee}


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    repo = os.path.dirname(here)
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("old")
    p.add_argument("new")
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--data", default=os.environ.get("FM_DATA_DIR", os.path.join(repo, "..", "shared", "data")))
    p.add_argument("--only", default="track,jtml,knee")
    a = p.parse_args()
    exes = {"old": os.path.abspath(a.old), "new": os.path.abspath(a.new)}
    results = {}  # (workload figure, which) -> list of values over runs
    with tempfile.TemporaryDirectory() as work:
        for r in range(a.runs):
            for name in a.only.split(","):
                for which in ("old", "new"):
                    figures = WORKLOADS[name](exes[which], repo, os.path.abspath(a.data), work)
                    for key, values in figures.items():
                        results.setdefault((key, which), []).extend(values)
                        print(f"run {r + 1} {which:3} {key:28} {' '.join(f'{v:.3f}' for v in values)}",
                              flush=True)
    print(f"\n{'figure':30} {'old median (range)':26} {'new median (range)':26} new/old")
    for key in dict.fromkeys(k for k, _ in results):
        old, new = results[(key, "old")], results[(key, "new")]
        mo, mn = statistics.median(old), statistics.median(new)
        print(f"{key:30} {mo:.3f} ({min(old):.3f}-{max(old):.3f})      {mn:.3f} ({min(new):.3f}-{max(new):.3f})"
              f"      {mn / mo:.2f}")


if __name__ == "__main__":
    main()
