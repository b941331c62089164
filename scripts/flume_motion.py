#!/usr/bin/python3
"""Which grains move, snapshot by snapshot, in a flume run (particles_*.vtu).

Usage: flume_motion.py [--rest V] RUN_DIR...
Kuen (2011, §6, Model 3) describes the motion from his snapshots: at 0.2 s the
lowest front grains accelerate fastest while the rearmost stay at rest; "only
after one second are all particles in motion"; between 1.0 and 1.2 s the first
grains come to rest on the barrier and then on the arc. Per snapshot this prints
the share of grains slower than V (default 0.01 m/s) and slower than 5 V, the
median speed, and the share of the resting grains that lie downstream of the
chute's end (on arc or barrier).
"""
import argparse
import csv
import json
import os
import re

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def chute_end_x(run):
    s_end = json.load(open(os.path.join(run, "summary.json")))["flume"]["path"]["chute_end_s"]
    rows = [(float(r["s"]), float(r["x"])) for r in csv.DictReader(open(os.path.join(run, "flume", "path.csv")))]
    s, x = zip(*rows)
    return float(np.interp(s_end, s, x))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("runs", nargs="+")
    p.add_argument("--rest", type=float, default=0.01, help="speed below which a grain rests [m/s]")
    a = p.parse_args()
    for run in a.runs:
        x_end = chute_end_x(run)
        pvd = open(os.path.join(run, "particles.pvd")).read()
        print(f"{run}: chute ends at x = {x_end:.3f} m")
        print("   t [s]  resting  below 5V  median speed [m/s]  resting grains past the chute")
        for t, name in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd):
            reader = vtk.vtkXMLUnstructuredGridReader()
            reader.SetFileName(os.path.join(run, name))
            reader.Update()
            grid = reader.GetOutput()
            v = vtk_to_numpy(grid.GetPointData().GetArray("velocity"))
            x = vtk_to_numpy(grid.GetPoints().GetData())[:, 0]
            speed = np.linalg.norm(v, axis=1)
            rest = speed < a.rest
            past = f"{np.mean(x[rest] > x_end) * 100:5.1f} %" if rest.any() else "    -"
            print(f"  {float(t):6.2f}  {np.mean(rest) * 100:5.1f} %  {np.mean(speed < 5 * a.rest) * 100:5.1f} %"
                  f"   {np.median(speed):8.3f}            {past}")


if __name__ == "__main__":
    main()
