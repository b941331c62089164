#!/usr/bin/python3
"""Which grains move, snapshot by snapshot, in a flume run (particles_*.vtu).

Feeds docs/validation/flume.md, section "Full runs (3 s of flow; ...)": which grains
move, against Kuen's description.

Usage: flume_motion.py [--rest V] RUN_DIR...
Kuen (2011, §6, Model 3) describes the motion from his snapshots: at 0.2 s the
lowest front grains accelerate fastest while the rearmost stay at rest; from
0.4 s the upper layers move faster than the lower ones and override them; "only
after one second are all particles in motion"; between 1.0 and 1.2 s the first
grains come to rest on the barrier and then on the arc. Per snapshot this prints
the share of grains slower than V (default 0.01 m/s) and slower than 5 V, the
median speed, the share of the resting grains that lie downstream of the
chute's end (on arc or barrier), and the mean speed along the chute of the grains
in the upper and the lower half of the local flow depth on the chute between the
gate and the arc (5 cm stretches of the chute, depth = the highest grain's height
above the bed in the stretch; stretches with fewer than 20 grains left out).
"""
import argparse
import csv
import json
import os
import re

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def chute(run):
    """Gate foot, unit vectors along (downstream) and normal (up) to the straight
    chute, and the chute's end as a path coordinate."""
    s_end = json.load(open(os.path.join(run, "summary.json")))["flume"]["path"]["chute_end_s"]
    rows = [(float(r["s"]), float(r["x"]), float(r["y"]))
            for r in csv.DictReader(open(os.path.join(run, "flume", "path.csv")))]
    s, x, y = (np.array(c) for c in zip(*rows))
    foot = np.array([np.interp(0.0, s, x), np.interp(0.0, s, y)])
    along = np.array([x[1] - x[0], y[1] - y[0]])
    along /= np.linalg.norm(along)
    return foot, along, np.array([-along[1], along[0]]), s_end


def upper_lower(p, v, frame):
    """Mean speed along the chute of the upper and lower half of the flow depth."""
    foot, along, up, s_end = frame
    s = (p - foot) @ along
    h = (p - foot) @ up
    u = v @ along
    upper, lower = [], []
    for lo in np.arange(0.0, s_end, 0.05):
        m = (s >= lo) & (s < lo + 0.05)
        if m.sum() < 20:
            continue
        depth = h[m].max()
        upper.extend(u[m][h[m] > 0.5 * depth])
        lower.extend(u[m][h[m] <= 0.5 * depth])
    if not upper or not lower:
        return "     -        -"
    return f"{np.mean(upper):8.3f} {np.mean(lower):8.3f}"


def main():
    p = argparse.ArgumentParser()
    p.add_argument("runs", nargs="+")
    p.add_argument("--rest", type=float, default=0.01, help="speed below which a grain rests [m/s]")
    a = p.parse_args()
    for run in a.runs:
        frame = chute(run)
        foot, along, _, s_end = frame
        x_end = (foot + s_end * along)[0]  # the chute is straight from the gate foot
        pvd = open(os.path.join(run, "particles.pvd")).read()
        print(f"{run}: chute ends at x = {x_end:.3f} m")
        print("   t [s]  resting  below 5V  median speed [m/s]  resting grains past the chute"
              "  speed on the chute [m/s]: upper half, lower half")
        for t, name in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd):
            reader = vtk.vtkXMLUnstructuredGridReader()
            reader.SetFileName(os.path.join(run, name))
            reader.Update()
            grid = reader.GetOutput()
            v = vtk_to_numpy(grid.GetPointData().GetArray("velocity"))
            pos = vtk_to_numpy(grid.GetPoints().GetData())[:, :2]
            x = pos[:, 0]
            speed = np.linalg.norm(v, axis=1)
            rest = speed < a.rest
            past = f"{np.mean(x[rest] > x_end) * 100:5.1f} %" if rest.any() else "    -"
            print(f"  {float(t):6.2f}  {np.mean(rest) * 100:5.1f} %  {np.mean(speed < 5 * a.rest) * 100:5.1f} %"
                  f"   {np.median(speed):8.3f}            {past}"
                  f"                  {upper_lower(pos, v[:, :2], frame)}")


if __name__ == "__main__":
    main()
