#!/usr/bin/python3
"""Single-step force peaks of flume runs, window by window, beside the mean force.

Feeds docs/validation/flume.md, section "Full runs (3 s of flow; ...)": the single-step
force peaks.

Usage: flume_force_peaks.py [--window W] [--from T0] [--to T1] RUN_DIR...
Reads flume/front.csv (columns <part>_f<c> = mean force over each series interval,
<part>_f<c>_peak = the largest force of a single step in it) and summary.json. For
each run, per window of W seconds (default 0.05, from 0.6 to 1.6 s): the barrier's
largest single-step F_x and largest interval-mean F_x, the arc's most negative
single-step and mean F_y. Then, per run, when the front reached arc and barrier
and when the barrier's largest single-step F_x and the arc's most negative
single-step F_y came. Kuen (2011, §7.2) reports the barrier's largest F_x when the
front arrives (0.8 s) and the arc's largest F_y before it (0.7 s).
"""
import argparse
import csv
import json
import os


def main():
    p = argparse.ArgumentParser()
    p.add_argument("runs", nargs="+")
    p.add_argument("--window", type=float, default=0.05)
    p.add_argument("--from", dest="t0", type=float, default=0.6)
    p.add_argument("--to", dest="t1", type=float, default=1.6)
    a = p.parse_args()
    lines = []
    for run in a.runs:
        rows = [{k: float(v) for k, v in r.items()}
                for r in csv.DictReader(open(os.path.join(run, "flume", "front.csv")))]
        flume = json.load(open(os.path.join(run, "summary.json")))["flume"]
        print(f"{run}: per {a.window * 1000:.0f} ms window [N/m]")
        print("  window [s]    | barrier F_x: step peak, mean peak | arc F_y: step peak, mean peak")
        n = 0
        while a.t0 + (n + 1) * a.window <= a.t1 + 1e-9:
            lo, hi = a.t0 + n * a.window, a.t0 + (n + 1) * a.window
            sel = [r for r in rows if lo < r["time"] <= hi + 1e-9]
            n += 1
            if not sel:
                continue
            print(f"  {lo:.2f}-{hi:.2f}     | {max(r['barrier_fx_peak'] for r in sel):8.0f} "
                  f"{max(r['barrier_fx'] for r in sel):8.0f}        | "
                  f"{min(r['arc_fy_peak'] for r in sel):8.0f} {min(r['arc_fy'] for r in sel):8.0f}")
        b, arc = flume["forces"]["barrier"], flume["forces"]["arc"]
        lines.append(f"{run}: front at the arc {flume['front']['reach_arc_time']:.3f} s, at the "
                     f"barrier {flume['front']['reach_barrier_time']:.3f} s; barrier step peak F_x "
                     f"{b['peak_step_fx']:.0f} N/m at {b['peak_step_fx_time']:.3f} s (mean peak "
                     f"{b['peak_fx']:.0f} at {b['peak_fx_time']:.3f}); arc step peak F_y "
                     f"{arc['peak_step_fy']:.0f} at {arc['peak_step_fy_time']:.3f} s (mean peak "
                     f"{arc['peak_fy']:.0f} at {arc['peak_fy_time']:.3f})")
    print()
    print("\n".join(lines))


if __name__ == "__main__":
    main()
