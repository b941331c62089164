#!/usr/bin/python3
"""Writes the synthetic terrain of scenarios/runout/runout_terrain_2d.toml as ESRI ASCII grids.

A 32 deg slope that eases into a flat valley floor along x (a parabolic
transition over 100 m), with a shallow gully down its middle; a 4 m high
barrier across the run-out as a separate obstacle raster; and a 60 m x 40 m
release area, 3 m thick, near the top. 90 x 50 cells of 5 m (450 m x 250 m),
lower-left corner at (600000, 5200000).
Usage: make_runout_terrain.py OUT_DIR [CELL]   (the bundled grids: scenarios/runout/runout_terrain;
CELL, default 5 m: the same terrain on finer cells, for benchmarks: bench/mpi_fv2d.sh)
"""
import math
import os
import sys

import esri_ascii

NX, NY, CELL = 90, 50, 5.0
X0, Y0 = 600000.0, 5200000.0


def bed(x, y):
    s = math.tan(math.radians(32))
    x1, x2 = 150.0, 250.0  # slope to x1, parabolic transition to x2, then flat
    if x < x1:
        z = s * (x2 - x) - s * (x2 - x1) / 2
    elif x < x2:
        z = s * (x2 - x) ** 2 / (2 * (x2 - x1))
    else:
        z = 0.0
    gully = -3.0 * math.exp(-(((y - 125.0) / 30.0) ** 2)) * min(1.0, max(0.0, (x2 - x) / 100.0))
    return z + gully


def write(path, value):
    esri_ascii.write(path, value, NX, NY, CELL, X0, Y0, decimals=3)


def main():
    global NX, NY, CELL
    out = sys.argv[1]
    if len(sys.argv) > 2:  # the same 450 m x 250 m on other cells
        CELL = float(sys.argv[2])
        NX, NY = round(450.0 / CELL), round(250.0 / CELL)
    os.makedirs(out, exist_ok=True)
    write(os.path.join(out, "terrain.asc"), bed)
    write(os.path.join(out, "barrier.asc"),
          lambda x, y: 4.0 if 265 <= x < 275 and 50 <= y < 200 else 0.0)
    write(os.path.join(out, "release.asc"),
          lambda x, y: 3.0 if 30 <= x < 90 and 105 <= y < 145 else 0.0)


if __name__ == "__main__":
    main()
