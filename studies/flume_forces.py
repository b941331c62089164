#!/usr/bin/python3
"""Wall forces of a flume run averaged over time windows, from its impulse columns.

Feeds docs/validation/flume.md, section "Full runs (3 s of flow; ...)": the windowed
wall forces.

Usage: flume_forces.py RUN_DIR [WINDOW_S] [T0 T1 STEP]
The series samples the instantaneous wall force every few milliseconds; a grain
flow makes it jump from sample to sample. The mean force over a window is the
change of the recorded impulse (the integral of the force over every step)
divided by the window, so no step is missed. Prints, per wall, the mean force
every STEP seconds (default 0.6-2.2 s every 0.1 s, window 0.02 s) and the
largest mean force in x and y with its time, and when each component settles:
the last window whose mean lies more than 10 % from the mean of the last 0.1 s.
"""
import csv
import os
import sys


def main():
    run = sys.argv[1]
    window = float(sys.argv[2]) if len(sys.argv) > 2 else 0.02
    t0, t1, dt = (float(v) for v in sys.argv[3:6]) if len(sys.argv) > 5 else (0.6, 2.2, 0.1)
    rows = list(csv.DictReader(open(os.path.join(run, "series.csv"))))
    t = [float(r["time"]) for r in rows]
    walls = [c[: -len("_impulse_x")] for c in rows[0] if c.endswith("_impulse_x")]

    def mean_force(wall, axis):
        imp = [float(r[f"{wall}_impulse_{axis}"]) for r in rows]
        out, j = [], 0
        for i in range(len(t)):
            while j < len(t) and t[j] < t[i] + window:
                j += 1
            if j == len(t):
                break
            out.append((0.5 * (t[i] + t[j]), (imp[j] - imp[i]) / (t[j] - t[i])))
        return out

    for wall in walls:
        fx, fy = mean_force(wall, "x"), mean_force(wall, "y")
        if not fx or max(abs(f) for _, f in fx + fy) == 0:
            continue
        print(f"{wall}: mean force over {window * 1000:.0f} ms [N/m]")
        print("   t [s]      Fx       Fy")
        k = 0
        while t0 + k * dt <= t1 + 1e-9:
            tt = t0 + k * dt
            i = min(range(len(fx)), key=lambda n: abs(fx[n][0] - tt))
            print(f"  {fx[i][0]:6.3f} {fx[i][1]:8.1f} {fy[i][1]:8.1f}")
            k += 1
        for name, series in (("Fx", fx), ("Fy", fy)):
            tm, fm = max(series, key=lambda p: abs(p[1]))
            print(f"  largest |{name}|: {fm:.1f} N/m at {tm:.3f} s")
            end = [f for tt, f in series if tt >= series[-1][0] - 0.1]
            final = sum(end) / len(end)
            off = [tt for tt, f in series if abs(f - final) > 0.1 * abs(final)]
            print(f"  {name} within 10 % of its final {final:.1f} N/m from {off[-1] if off else 0:.3f} s")


if __name__ == "__main__":
    main()
