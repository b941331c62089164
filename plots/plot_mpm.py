#!/usr/bin/python3
"""Plots of an MPM run folder (talus run on a method = "mpm" scenario).

Usage: plot_mpm.py RUN_DIR   (writes RUN_DIR/plots/*.png and prints their paths)
  front.png     front position and top of the material against time, with the
                kinetic energy (series.csv)
  profile.png   the final deposit: the highest point in each column of point
                spacing against x (last particles_*.vtu)
  snapshots.png the points at up to four snapshot times, coloured by the
                accumulated plastic shear strain (particles_*.vtu via VTK)
Uses Debian's matplotlib and python3-vtk9; run with /usr/bin/python3.
"""
import glob
import os
import sys
import xml.etree.ElementTree as ET

import matplotlib
from talus_csv import read_columns

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from vtk import vtkXMLUnstructuredGridReader  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402


def snapshots(run, name="particles"):
    """[(time, vtu path)] from the .pvd collection."""
    pvd = os.path.join(run, name + ".pvd")
    if not os.path.exists(pvd):
        return []
    root = ET.parse(pvd).getroot()
    return [(float(d.get("timestep")), os.path.join(run, d.get("file")))
            for d in root.iter("DataSet")]


def read_points(path, fields=("plastic_strain", "radius")):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    xyz = vtk_to_numpy(grid.GetPoints().GetData())
    data = {f: vtk_to_numpy(grid.GetPointData().GetArray(f)) for f in fields}
    return xyz, data


def profile(xyz, radius):
    """Highest point top (y + radius) per bin of one point spacing along x."""
    dx = 2.0 * float(np.median(radius))
    bins = np.floor(xyz[:, 0] / dx).astype(int)
    xs, tops = [], []
    for b in np.unique(bins):
        sel = bins == b
        xs.append((b + 0.5) * dx)
        tops.append(float(np.max(xyz[sel, 1] + radius[sel])))
    return np.array(xs), np.array(tops)


def main():
    run = sys.argv[1]
    out = os.path.join(run, "plots")
    os.makedirs(out, exist_ok=True)
    written = []
    s = read_columns(os.path.join(run, "series.csv"))
    t = s["time"]

    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(t, s["front_x"], label="front x (furthest point) [m]")
    ax.plot(t, s["top"], label="top (highest point) [m]")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("position [m]")
    ax.grid(alpha=0.3)
    ke = ax.twinx()
    ke.plot(t, s["kinetic_energy"], "k:", label="kinetic energy")
    ke.set_ylabel("kinetic energy [J]")
    lines = ax.get_lines() + ke.get_lines()
    ax.legend(lines, [ln.get_label() for ln in lines], loc="center right")
    fig.tight_layout()
    written.append(os.path.join(out, "front.png"))
    fig.savefig(written[-1], dpi=120)

    snaps = snapshots(run)
    if snaps:
        xyz0, d0 = read_points(snaps[0][1])
        xyz1, d1 = read_points(snaps[-1][1])
        fig, ax = plt.subplots(figsize=(8, 3.5))
        for (time, _), xyz, d, style in ((snaps[0], xyz0, d0, "k--"), (snaps[-1], xyz1, d1, "C0-")):
            x, top = profile(xyz, d["radius"])
            ax.plot(x, top, style, drawstyle="steps-mid", label=f"t = {time:.3g} s")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("surface height [m]")
        ax.set_aspect("equal", adjustable="datalim")
        ax.legend()
        ax.grid(alpha=0.3)
        fig.tight_layout()
        written.append(os.path.join(out, "profile.png"))
        fig.savefig(written[-1], dpi=120)

        picks = sorted({round(i * (len(snaps) - 1) / 3) for i in range(4)})
        frames = [(snaps[i][0], *read_points(snaps[i][1])) for i in picks]
        vmax = max(float(np.max(d["plastic_strain"])) for _, _, d in frames) or 1.0
        boundary = dict(snapshots(run, "boundary"))
        fig, axes = plt.subplots(len(frames), 1, figsize=(8, 2.4 * len(frames)), squeeze=False,
                                 layout="constrained")
        for ax, (time, xyz, d) in zip(axes[:, 0], frames):
            if time in boundary:
                bxyz, _ = read_points(boundary[time], fields=())
                ax.scatter(bxyz[:, 0], bxyz[:, 1], s=2, c="0.6", linewidths=0)
            sc = ax.scatter(xyz[:, 0], xyz[:, 1], s=3, c=d["plastic_strain"], cmap="viridis",
                            vmin=0.0, vmax=vmax, linewidths=0)
            ax.set_aspect("equal")
            ax.set_title(f"t = {time:.3g} s", fontsize=9)
            ax.set_ylabel("y [m]")
        axes[-1, 0].set_xlabel("x [m]")
        fig.colorbar(sc, ax=axes[:, 0].tolist(), label="plastic shear strain")
        written.append(os.path.join(out, "snapshots.png"))
        fig.savefig(written[-1], dpi=120)

    for path in written:
        print(path)


if __name__ == "__main__":
    main()
