#!/usr/bin/python3
"""Plots of a 1D DAN runout run (model dan).

Usage: plot_dan.py RUN_DIR   (writes RUN_DIR/plots/*.png and prints their paths)
front.png:   front position along the path versus time (front.csv), with the
             barrier arrival and the largest run-up from summary.json.
deposit.png: the final deposit's free surface (deposit.csv) over the bed
             (path.csv), equal axes, with the run-up point (highest bed point the
             front reached, during the run and in the final deposit).
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from talus_csv import read_columns  # noqa: E402


def finite(v):
    return isinstance(v, (int, float)) and math.isfinite(v)


def main():
    run = sys.argv[1]
    summary = json.load(open(os.path.join(run, "summary.json")))
    m = summary["metrics"]
    name = summary["scenario"].get("name", os.path.basename(run))
    out_dir = os.path.join(run, "plots")
    os.makedirs(out_dir, exist_ok=True)
    written = []

    front = read_columns(os.path.join(run, "front.csv"))
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(front["time"], front["s"], "k-", label="front")
    arrival = m.get("barrier_arrival_time_s")
    if finite(arrival):
        ax.axvline(arrival, color="tab:red", ls=":", label=f"barrier reached {arrival:.2f} s")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("front s along the path [m]")
    ax.set_title(f"{name}: front")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right")
    path = os.path.join(out_dir, "front.png")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    written.append(path)

    bed = read_columns(os.path.join(run, "path.csv"))
    dep = read_columns(os.path.join(run, "deposit.csv"))
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(bed["x"], bed["y"], "k-", lw=1.5, label="bed")
    # The deposit as a filled band between bed and surface points.
    poly_x = dep["x_bed"] + dep["x_surface"][::-1]
    poly_y = dep["y_bed"] + dep["y_surface"][::-1]
    ax.fill(poly_x, poly_y, color="tan", alpha=0.8, label="final deposit")
    ax.plot(dep["x_surface"], dep["y_surface"], color="saddlebrown", lw=1)
    for key, style, label in (("runup_max", "rv", "run-up, max"), ("runup_final", "b^", "run-up, final")):
        r = m.get(key, {})
        if finite(r.get("elevation_m")) and finite(r.get("s_m")):
            # The bed point at s (path.csv is sampled every 5 mm).
            k = min(range(len(bed["s"])), key=lambda i: abs(bed["s"][i] - r["s_m"]))
            ax.plot(bed["x"][k], r["elevation_m"], style, ms=7,
                    label=f"{label}: y = {r['elevation_m']:.3f} m")
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(f"{name}: deposit at t = {summary['run']['simulated_time_s']:.2f} s")
    ax.legend(loc="upper right", fontsize=8)
    ax.grid(alpha=0.3)
    path = os.path.join(out_dir, "deposit.png")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    written.append(path)
    for p in written:
        print(p)


if __name__ == "__main__":
    main()
