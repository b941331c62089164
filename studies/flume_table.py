#!/usr/bin/python3
"""The table of full flume runs in docs/validation.md, from their run folders.

Feeds docs/validation/flume.md, section "Full runs (3 s of flow; ...)": the table of
full runs.

Usage: flume_table.py LABEL=RUN_DIR ...   (prints a Markdown table)
Numbers come from each run's summary.json ("flume"), except the surface slope:
the least-squares slope of the deposit's top (highest grain top per 1 cm
column of the final frame) between the tail and the barrier foot, in degrees
(0 = horizontal; Kuen: Model 2 spreads out almost flat).
"""
import csv
import glob
import json
import math
import os
import sys


def surface_slope(run, f):
    frame = sorted(glob.glob(os.path.join(run, "flume", "frames", "t_*.csv")))[-1]
    path = list(csv.DictReader(open(os.path.join(run, "flume", "path.csv"))))
    def x_at(s):
        return float(min(path, key=lambda r: abs(float(r["s"]) - s))["x"])
    x0, x1 = x_at(f["deposit"]["tail_s"]), x_at(f["path"]["arc_end_s"])
    top = {}
    for r in csv.DictReader(open(frame)):
        x, y, rad = float(r["x"]), float(r["y"]), float(r["r"])
        if x0 <= x <= x1:
            k = int(x / 0.01)
            top[k] = max(top.get(k, -1e9), y + rad)
    xs = [(k + 0.5) * 0.01 for k in top]
    ys = list(top.values())
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    slope = sum((a - mx) * (b - my) for a, b in zip(xs, ys)) / sum((a - mx) ** 2 for a in xs)
    return math.degrees(math.atan(slope))


print("| run | grains | reaches arc [s] | reaches barrier [s] | run-up along barrier, final (max) [m] "
      "| run-up height above bed low point [m] | main deposit starts, s [m] | stranded | "
      "surface slope tail-barrier [deg] | setup + loop [s] |")
print("|---|---|---|---|---|---|---|---|---|---|")
for arg in sys.argv[1:]:
    label, run = arg.split("=", 1)
    j = json.load(open(os.path.join(run, "summary.json")))
    f = j["flume"]
    print(f"| {label} | {f['deposit']['particles']} | {f['front']['reach_arc_time']:.3f} "
          f"| {f['front']['reach_barrier_time']:.3f} | {f['runup']['final_s']:.3f} "
          f"({f['runup']['max_s']:.3f}) | {f['runup']['final_height']:.3f} "
          f"| {f['deposit']['tail_s']:.3f} | {f['deposit']['stranded']} "
          f"| {surface_slope(run, f):.1f} | {j['run']['setup_wall_s']:.0f} + {j['run']['loop_wall_s']:.0f} |")
