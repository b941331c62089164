#!/usr/bin/python3
"""Writes the synthetic valley of scenarios/runout/two_phase_debris_valley.toml as ESRI ASCII grids.

A torrent channel descending along x: 22 deg in the source reach, easing
(parabolic, over 150 m) to a 3 deg fan; a V-shaped cross-section (side
slopes of 1 in 3) that widens out onto the fan. A saturated release, 2.5 m
thick over 50 m x 40 m, in the channel near the top; its solid fraction
falls from 0.65 at the back to 0.45 at the front (a wetter snout), written as
a raster. 100 x 50 cells of 5 m (500 m x 250 m), lower-left corner at
(600000, 5200000).
Usage: make_debris_valley.py OUT_DIR   (the bundled grids: scenarios/runout/debris_valley)
"""
import math
import os
import sys

import esri_ascii

NX, NY, CELL = 100, 50, 5.0
X0, Y0 = 600000.0, 5200000.0
X_BEND, X_FAN = 150.0, 300.0  # the channel eases from X_BEND to X_FAN


def long_profile(x):
    steep, fan = math.tan(math.radians(22)), math.tan(math.radians(3))
    if x < X_BEND:
        return steep * (X_BEND - x) + 0.5 * (steep + fan) * (X_FAN - X_BEND) + fan * (NX * CELL - X_FAN)
    if x < X_FAN:  # the slope falls linearly from steep to fan
        t = x - X_BEND
        length = X_FAN - X_BEND
        drop = steep * t - 0.5 * (steep - fan) * t * t / length
        return long_profile(X_BEND - 1e-9) - drop
    return fan * (NX * CELL - x)


def bed(x, y):
    # Side slopes 1:3 in the channel, 1:30 on the fan, between them a blend.
    w = min(1.0, max(0.0, (X_FAN - x) / (X_FAN - X_BEND)))
    side = 1.0 / 30.0 + w * (1.0 / 3.0 - 1.0 / 30.0)
    return long_profile(x) + side * abs(y - 125.0)


def release(x, y):
    return 2.5 if 20 <= x < 70 and 105 <= y < 145 else 0.0


def solid_fraction(x, y):
    if release(x, y) == 0.0:
        return 0.0
    return 0.65 - 0.2 * (x - 20.0) / 50.0


def write(path, value):
    esri_ascii.write(path, value, NX, NY, CELL, X0, Y0, decimals=4)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    write(os.path.join(out, "terrain.asc"), bed)
    write(os.path.join(out, "release.asc"), release)
    write(os.path.join(out, "solid_fraction.asc"), solid_fraction)


if __name__ == "__main__":
    main()
