#!/usr/bin/python3
"""Flume runs side by side for a time-step study (docs/validation.md, "Time step").

Feeds docs/validation/flume.md, section "Time step: Model 3's deposit on the chute
depends on it": its table.

Usage: flume_step_table.py LABEL=RUN_DIR ...   (prints a Markdown table)
Per run, from summary.json and flume/deposit_profile.csv: the step, when the
front reaches the barrier, the final run-up along the barrier, where the main
deposit starts and how many grains are stranded upstream of it (the flume
report's definitions), the grains resting on the chute upstream of the
s = 0.40 m mark (the lab's "40 cm" of the thesis), and the barrier's impulses
over the whole run. Works without snapshots (`output.snapshots = false`).
"""
import csv
import json
import os
import sys


def grains_upstream(run, s_mark):
    rows = csv.DictReader(open(os.path.join(run, "flume", "deposit_profile.csv")))
    return sum(int(r["count"]) for r in rows if float(r["s_high"]) <= s_mark + 1e-9)


print("| run | step [µs] | reaches barrier [s] | run-up along barrier [m] | main deposit starts, "
      "s [m] | stranded | grains upstream of s = 0.40 m | barrier impulse x / y [N s/m] |")
print("|---|---|---|---|---|---|---|---|")
for arg in sys.argv[1:]:
    label, _, run = arg.partition("=")
    j = json.load(open(os.path.join(run, "summary.json")))
    f = j["flume"]
    b = f["forces"]["barrier"]
    print(f"| {label} | {j['resolved']['time_step_s'] * 1e6:.2f} | "
          f"{f['front']['reach_barrier_time']:.3f} | {f['runup']['final_s']:.3f} | "
          f"{f['deposit']['tail_s']:.3f} | {f['deposit']['stranded']} | "
          f"{grains_upstream(run, 0.40)} | {b['impulse_x']:.0f} / {b['impulse_y']:.0f} |")
