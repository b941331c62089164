#!/usr/bin/python3
"""Plots of MPM runs with membranes (the geotextile bag, scenarios/mpm/mpm_geotextile_bag*.toml).

Usage:
  plot_mpm_geotextile.py RUN_DIR [TIMES...]
      RUN_DIR/plots/tension.png  largest membrane tension against time (membranes.csv)
      RUN_DIR/plots/shapes.png   sand points, the membrane coloured by its tension and the
                                 barge's boundary particles at the snapshot times nearest
                                 to TIMES (default: six spread over the run)
  plot_mpm_geotextile.py --compare OUT.png RUN_DIR:LABEL [RUN_DIR:LABEL ...]
      the largest tension of several runs against time in one plot
Uses Debian's matplotlib and python3-vtk9; run with /usr/bin/python3.
"""
import os
import sys

import matplotlib
from plot_mpm import read_points, snapshots
from talus_csv import read_columns

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def tension_plot(run, out):
    s = read_columns(os.path.join(run, "membranes.csv"))
    fig, ax = plt.subplots(figsize=(7, 3.5))
    ax.plot(s["time"], np.asarray(s["max_tension"]) / 1e3, label="largest tension")
    for key in s:
        if key.endswith("_mean_tension"):
            ax.plot(s["time"], np.asarray(s[key]) / 1e3, ":", label=key.replace("_", " "))
    ax.set_xlabel("time [s]")
    ax.set_ylabel("membrane tension [kN/m]")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def nearest(frames, t):
    return min(frames, key=lambda f: abs(f[0] - t))


def shapes_plot(run, out, times):
    parts, mems = snapshots(run, "particles"), snapshots(run, "membranes")
    bound = snapshots(run, "boundary")
    if not times:
        end = parts[-1][0]
        times = [end * k / 5.0 for k in range(6)]
    cols = 3
    rows = (len(times) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.3 * rows), squeeze=False)
    tmax = 0.0
    frames = []
    for t in times:
        tp, pp = nearest(parts, t)
        _, mp = nearest(mems, tp)
        xyz, _ = read_points(pp, ())
        mxyz, md = read_points(mp, ("tension", "material"))
        bxyz = read_points(nearest(bound, tp)[1], ())[0] if bound else None
        tmax = max(tmax, float(np.max(md["tension"])))
        frames.append((tp, xyz, mxyz, md, bxyz))
    for ax, (tp, xyz, mxyz, md, bxyz) in zip(axes.flat, frames):
        ax.scatter(xyz[:, 0], xyz[:, 1], s=1, c="0.75", linewidths=0)
        if bxyz is not None:
            ax.scatter(bxyz[:, 0], bxyz[:, 1], s=1, c="k", linewidths=0)
        sc = ax.scatter(mxyz[:, 0], mxyz[:, 1], s=4, c=md["tension"] / 1e3, cmap="plasma",
                        vmin=0.0, vmax=tmax / 1e3, linewidths=0)
        ax.set_title(f"t = {tp:.2f} s")
        ax.set_aspect("equal")
        ax.set_xlim(-4.5, 4.5)
        ax.set_ylim(0.0, 7.5)
    for ax in list(axes.flat)[len(frames):]:
        ax.axis("off")
    fig.colorbar(sc, ax=axes, shrink=0.8, label="membrane tension [kN/m]")
    fig.savefig(out, dpi=110)
    plt.close(fig)


def compare_plot(out, runs):
    fig, ax = plt.subplots(figsize=(7, 3.8))
    for spec in runs:
        run, label = spec.split(":", 1)
        s = read_columns(os.path.join(run, "membranes.csv"))
        ax.plot(s["time"], np.asarray(s["max_tension"]) / 1e3, label=label)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("largest membrane tension [kN/m]")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print(out)


def main():
    if sys.argv[1] == "--compare":
        compare_plot(sys.argv[2], sys.argv[3:])
        return
    run = sys.argv[1]
    out = os.path.join(run, "plots")
    os.makedirs(out, exist_ok=True)
    tension_plot(run, os.path.join(out, "tension.png"))
    shapes_plot(run, os.path.join(out, "shapes.png"), [float(t) for t in sys.argv[2:]])
    print(os.path.join(out, "tension.png"))
    print(os.path.join(out, "shapes.png"))


if __name__ == "__main__":
    main()
