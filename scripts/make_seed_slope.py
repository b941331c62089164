#!/usr/bin/python3
"""Writes the terrain of scenarios/runout/two_phase_seed_section4.toml as ESRI ASCII grids.

The numerical tests of van den Bout et al. (2021) §4 release blocks on a
slope that runs into a valley; their geometry is drawn in the paper's Fig. 6
only, which the text source does not hold. This is a stand-in of that kind,
on the paper's 10 m cells: a 30 deg slope (x < 300 m) into a 100 m flat
valley floor and a 20 deg counter-slope (x > 400 m); a block 100 m x 100 m,
10 m high (10^5 m^3), released on the slope. 60 x 40 cells of 10 m.
Usage: make_seed_slope.py OUT_DIR   (the bundled grids: scenarios/runout/seed_slope)
"""
import math
import os
import sys

import esri_ascii

NX, NY, CELL = 60, 40, 10.0
X0, Y0 = 600000.0, 5200000.0


def bed(x, _y):
    if x < 300.0:
        return math.tan(math.radians(30)) * (300.0 - x)
    if x < 400.0:
        return 0.0
    return math.tan(math.radians(20)) * (x - 400.0)


def block(x, y):
    return 10.0 if 50 <= x < 150 and 150 <= y < 250 else 0.0


def write(path, value):
    esri_ascii.write(path, value, NX, NY, CELL, X0, Y0, decimals=4)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    write(os.path.join(out, "terrain.asc"), bed)
    write(os.path.join(out, "release.asc"), block)


if __name__ == "__main__":
    main()
