"""Wall time of register's confirmed search on the JTML frame 0170 (docs/real-xray.md, "Verdicts
and uncertainty"): one search against two from independent starts, one implant and both, three
alternating repetitions.
  PYTHONPATH=build/python /usr/bin/python3 scripts/time_confirmed_register.py
"""
import os
import time

import fluoromatch as fm

D = os.path.join(os.environ.get("FM_DATA_DIR", "../shared/data"), "jtml-kneel-tka-fluoro")
ref, cal = os.path.join(D, "AT_K1_V1_0170.tif"), os.path.join(D, "calibration.txt")
fem, tib = fm.read_mesh(os.path.join(D, "KR_right_7_fem.stl")), fm.read_mesh(os.path.join(D, "KR_right_6_tib.stl"))
cases = (([tib], ["tib.jts"], "tibia"), ([fem], ["fem.jts"], "femur"), ([fem, tib], ["fem.jts", "tib.jts"], "both"))
for rep in range(3):
    for runs in (1, 2):
        for models, starts, name in cases:
            t0 = time.perf_counter()
            answers = fm.register(ref, cal, models, [os.path.join(D, s) for s in starts], frame=1, invert=True,
                                  threads=2, runs=runs, max_runs=max(runs, 4))
            call = time.perf_counter() - t0
            print(f"rep {rep} runs {runs} {name:6s} registration wall {answers[0]['wall_seconds']:.3f} s, "
                  f"call {call:.3f} s, verdicts {[a['verdict'] for a in answers]}", flush=True)
