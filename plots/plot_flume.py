#!/usr/bin/python3
"""Pictures of a talus flume run (scenario with [flume]), as in Kuen's figures.

Usage: plot_flume.py RUN_DIR   (writes RUN_DIR/plots/flume_*.png and prints their paths)
  flume_snapshots.png  the flow every snapshot interval, grains coloured by initial layer
  flume_front.png      front position along the path versus time
  flume_deposit.png    final deposit surface over the bed, with the tail and run-up
  flume_forces.png     mean force on chute, arc and barrier (x and y) versus time
  flume_force_peaks.png  the largest single-step force in each interval, over the mean
Uses Debian's matplotlib; run with /usr/bin/python3.
"""
import glob
import json
import math
import os
import sys

import matplotlib
from talus_csv import read_columns

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402


def draw_bed(ax, path):
    ax.plot(path["x"], path["y"], color="0.2", lw=1.2)


def draw_grains(ax, frame, layers):
    xy = list(zip(frame["x"], frame["y"]))
    d = [2 * r for r in frame["r"]]
    cmap = plt.get_cmap("viridis", layers)
    colours = [cmap(int(k)) for k in frame["layer"]]
    ax.add_collection(EllipseCollection(d, d, [0] * len(d), units="xy", offsets=xy,
                                        offset_transform=ax.transData, facecolors=colours,
                                        edgecolors="none"))


def save(fig, out, filename, dpi):
    """Writes the figure to out/filename and returns that path."""
    fig.tight_layout()
    name = os.path.join(out, filename)
    fig.savefig(name, dpi=dpi)
    plt.close(fig)
    return name


def force_axes():
    """The two stacked panels (F_x above F_y) of the force figures."""
    fig, axes = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    axes[0].set_ylabel("F_x on the wall [N/m]")
    axes[1].set_ylabel("F_y on the wall [N/m]")
    axes[1].set_xlabel("time [s]")
    for ax in axes:
        ax.grid(alpha=0.3)
    return fig, axes


def snapshots(run, path, layers, out):
    frames = sorted(glob.glob(os.path.join(run, "flume", "frames", "t_*.csv")))
    if not frames:
        return None
    n = len(frames)
    cols = min(4, n)
    rows = math.ceil(n / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 2.6 * rows), squeeze=False)
    for ax in axes.flat:
        ax.set_axis_off()
    for ax, name in zip(axes.flat, frames):
        t = float(os.path.basename(name)[2:-4])
        draw_bed(ax, path)
        draw_grains(ax, read_columns(name), layers)
        ax.set_aspect("equal")
        ax.set_xlim(min(path["x"]) - 0.02, max(path["x"]) + 0.02)
        ax.set_ylim(min(path["y"]) - 0.05, max(path["y"]) + 0.05)
        ax.set_title(f"t = {t:.2f} s", fontsize=9)
    fig.suptitle("grains coloured by their initial layer (bottom = dark)")
    return save(fig, out, "flume_snapshots.png", 110)


def front_plot(front, summary, out):
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(front["time"], front["front_s"], label=f"front ({summary['front']['quantile']} quantile)")
    p = summary["path"]
    ax.axhline(p["chute_end_s"], color="0.6", ls="--", lw=0.8, label="arc starts")
    ax.axhline(p["arc_end_s"], color="0.3", ls="--", lw=0.8, label="barrier starts")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("path distance from the gate [m]")
    ax.legend()
    ax.grid(alpha=0.3)
    return save(fig, out, "flume_front.png", 120)


def deposit_plot(run, path, summary, layers, out):
    surface_csv = os.path.join(run, "flume", "deposit_surface.csv")
    fig, ax = plt.subplots(figsize=(9, 4))
    frames = sorted(glob.glob(os.path.join(run, "flume", "frames", "t_*.csv")))
    if frames:
        draw_grains(ax, read_columns(frames[-1]), layers)
    draw_bed(ax, path)
    if os.path.exists(surface_csv):  # runs of talus before 2026-11-22 lack it
        surface = read_columns(surface_csv)
        ax.plot(surface["x"], surface["y"], color="C3", lw=1, label="deposit surface")
    tail = summary["deposit"]["tail_s"]
    i = min(range(len(path["s"])), key=lambda k: abs(path["s"][k] - tail))
    ax.plot(path["x"][i], path["y"][i], "v", color="C1", ms=9,
            label=f"main deposit starts (s = {tail:.2f} m)")
    r = summary["runup"]
    ax.set_title(f"final deposit: run-up {r['final_height']:.3f} m above the bed low point "
                 f"({r['final_s']:.3f} m along the barrier)", fontsize=10)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.legend(loc="upper left", fontsize=8)
    return save(fig, out, "flume_deposit.png", 130)


def forces_plot(front, summary, out):
    fig, axes = force_axes()
    for part, colour in (("chute", "C0"), ("arc", "C1"), ("barrier", "C2")):
        axes[0].plot(front["time"], front[part + "_fx"], color=colour, label=part)
        axes[1].plot(front["time"], front[part + "_fy"], color=colour, label=part)
    weight = summary["deposit"]["weight_per_m"]
    axes[1].axhline(-weight, color="0.4", ls=":", label="total weight of the grains")
    for ax in axes:
        ax.legend(fontsize=8)
    fig.suptitle("mean force over each series interval, per metre of flume width")
    return save(fig, out, "flume_forces.png", 120)


def force_peaks_plot(front, out):
    """The largest force of a single step in each series interval (what a force
    sensor read every step records: a grain's impact lasts a few dozen steps),
    with the interval's mean underneath."""
    if "barrier_fx_peak" not in front:
        return None
    fig, axes = force_axes()
    for part, colour in (("chute", "C0"), ("arc", "C1"), ("barrier", "C2")):
        for ax, c in zip(axes, ("fx", "fy")):
            ax.plot(front["time"], front[f"{part}_{c}_peak"], color=colour, lw=0.7,
                    label=f"{part}, single step")
            ax.plot(front["time"], front[f"{part}_{c}"], color=colour, lw=1.6, alpha=0.45,
                    label=f"{part}, interval mean")
    for ax in axes:
        ax.legend(fontsize=7, ncol=3)
    fig.suptitle("largest single-step force in each series interval, per metre of width")
    return save(fig, out, "flume_force_peaks.png", 120)


def main():
    run = sys.argv[1]
    out = os.path.join(run, "plots")
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(run, "summary.json")) as f:
        summary = json.load(f)["flume"]
    layers = int(max(read_columns(os.path.join(run, "flume", "layers.csv"))["layer"]) + 1)
    path = read_columns(os.path.join(run, "flume", "path.csv"))
    front = read_columns(os.path.join(run, "flume", "front.csv"))
    for name in (snapshots(run, path, layers, out), front_plot(front, summary, out),
                 deposit_plot(run, path, summary, layers, out), forces_plot(front, summary, out),
                 force_peaks_plot(front, out)):
        if name:
            print(name)


if __name__ == "__main__":
    main()
