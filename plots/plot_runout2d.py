#!/usr/bin/python3
"""Maps of a 2D runout run (model fv2d or two_phase) over a hillshade of the terrain.

Usage: plot_runout2d.py RUN_DIR   (writes RUN_DIR/plots/*.png and prints their paths)
Reads the .npy copies of the result rasters (numpy only: Debian's python3 has no
GDAL bindings here) and summary.json for the grid's corner and cell size.
"""
import json
import os
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def hillshade(z, dx, dy, azimuth=315.0, altitude=45.0):
    # Rows run south, so d/dy of the map is minus d/d(row).
    gy, gx = np.gradient(z, dy, dx)
    slope = np.arctan(np.hypot(gx, -gy))
    aspect = np.arctan2(-gy, -gx)
    az, alt = np.radians(360.0 - azimuth + 90.0), np.radians(altitude)
    return np.sin(alt) * np.cos(slope) + np.cos(alt) * np.sin(slope) * np.cos(az - aspect)


def main():
    run = sys.argv[1]
    summary = json.load(open(os.path.join(run, "summary.json")))
    res = summary["resolved"]
    dx, dy = res["cell_size_m"]
    z = np.load(os.path.join(run, "elevation.npy"))
    ny, nx = z.shape
    extent = [0, nx * dx, 0, ny * dy]  # metres from the south-west corner
    shade = hillshade(z, dx, dy)
    out = os.path.join(run, "plots")
    os.makedirs(out, exist_ok=True)
    if summary.get("model") == "two_phase":
        maps = [("max_height", "maximum mixture height (m)", "viridis"),
                ("max_solid_speed", "maximum solid speed (m/s)", "plasma"),
                ("max_fluid_speed", "maximum fluid speed (m/s)", "plasma"),
                ("max_pressure", "maximum impact pressure (kPa)", "inferno"),
                ("deposit", "deposit height, mixture (m)", "viridis"),
                ("deposit_solid", "deposit height, solid (m)", "viridis"),
                ("solid_fraction", "solid fraction of the deposit", "cividis")]
    else:
        maps = [("max_height", "maximum flow height (m)", "viridis"),
                ("max_speed", "maximum speed (m/s)", "plasma"),
                ("max_pressure", "maximum pressure rho v^2 (kPa)", "inferno"),
                ("deposit", "deposit height (m)", "viridis")]
    for name, label, cmap in maps:
        a = np.load(os.path.join(run, name + ".npy"))
        if name == "solid_fraction":  # NaN where dry: shown where the deposit exceeds 1 cm
            deposit = np.load(os.path.join(run, "deposit.npy"))
            a = np.where(deposit > 0.01, np.nan_to_num(a), 0.0)
        if name.endswith("pressure"):
            a = a / 1000.0
        fig, ax = plt.subplots(figsize=(8, 8 * ny / nx + 1))
        ax.imshow(shade, cmap="gray", extent=extent, origin="upper")
        ax.contour(np.flipud(z), levels=12, colors="k", linewidths=0.3, alpha=0.5,
                   extent=extent)
        shown = np.ma.masked_where(a <= 0.01 * max(a.max(), 1e-12), a)
        im = ax.imshow(shown, cmap=cmap, alpha=0.85, extent=extent, origin="upper")
        fig.colorbar(im, ax=ax, label=label, shrink=0.8)
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        ax.set_title(f"{summary['scenario']['name']}: {label}")
        path = os.path.join(out, name + ".png")
        fig.savefig(path, dpi=110, bbox_inches="tight")
        plt.close(fig)
        print(path)


if __name__ == "__main__":
    main()
