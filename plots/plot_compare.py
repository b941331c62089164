#!/usr/bin/python3
"""Plots of a `talus compare` folder: every method on the same axes.

Usage: plot_compare.py COMPARE_DIR   (writes COMPARE_DIR/plots/compare_*.png, prints their paths)
  compare_front.png    front position along the path versus time
  compare_deposit.png  final deposit surfaces over the flume bed
Uses Debian's matplotlib; run with /usr/bin/python3.
"""
import json
import os
import sys

import matplotlib
from talus_csv import read_columns

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    out = sys.argv[1]
    report = json.load(open(os.path.join(out, "comparison.json")))
    methods = list(report["methods"])
    data = os.path.join(out, "compare")
    os.makedirs(os.path.join(out, "plots"), exist_ok=True)

    fig, ax = plt.subplots(figsize=(6.5, 4))
    for m in methods:
        f = read_columns(os.path.join(data, f"front_{m}.csv"))
        ax.plot(f["time"], f["s"], label=m.upper())
    ax.axhline(report["barrier_start_s"], color="0.3", ls="--", lw=0.8, label="barrier starts")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("front: path distance from the gate [m]")
    ax.set_title(report["name"])
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    front = os.path.join(out, "plots", "compare_front.png")
    fig.savefig(front, dpi=120)
    plt.close(fig)

    path = read_columns(os.path.join(data, "path.csv"))
    fig, ax = plt.subplots(figsize=(9, 4))
    ax.plot(path["x"], path["y"], color="0.2", lw=1.2, label="bed")
    for m in methods:
        s = read_columns(os.path.join(data, f"surface_{m}.csv"))
        r = report["methods"][m]
        ax.plot(s["x"], s["y"], lw=1.2,
                label=f"{m.upper()} (run-up {r['runup_along_barrier_m'] or 0:.3f} m along the barrier)")
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.legend(fontsize=8, loc="upper center")
    ax.set_title("final deposit surface")
    fig.tight_layout()
    deposit = os.path.join(out, "plots", "compare_deposit.png")
    fig.savefig(deposit, dpi=130)
    plt.close(fig)
    print(front)
    print(deposit)


if __name__ == "__main__":
    main()
