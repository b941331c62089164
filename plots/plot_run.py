#!/usr/bin/python3
"""Headline plots of a talus run folder: energies, contacts and wall forces over time.

Usage: plot_run.py RUN_DIR   (writes RUN_DIR/plots/*.png and prints their paths)
Uses Debian's matplotlib; run with /usr/bin/python3.
"""
import os
import sys

import matplotlib
from talus_csv import read_columns

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    run = sys.argv[1]
    s = read_columns(os.path.join(run, "series.csv"))
    out = os.path.join(run, "plots")
    os.makedirs(out, exist_ok=True)
    t = s["time"]
    written = []

    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(t, s["kinetic_energy"], label="translational")
    ax.plot(t, s["rotational_energy"], label="rotational")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("kinetic energy [J]")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    written.append(os.path.join(out, "energy.png"))
    fig.savefig(written[-1], dpi=120)

    walls = sorted({c[: -len("_fx")] for c in s if c.endswith("_fx")})
    if walls:
        fig, ax = plt.subplots(figsize=(7, 4))
        # Colour per wall, line style per axis, so a dozen curves stay apart.
        styles = {"x": "-", "y": "--", "z": ":"}
        for k, w in enumerate(walls):
            for axis in ("x", "y", "z"):
                key = f"{w}_f{axis}"
                if key in s and any(abs(v) > 0 for v in s[key]):
                    ax.plot(t, s[key], styles[axis], color=f"C{k % 10}", label=f"{w} F{axis}")
        ax.set_xlabel("time [s]")
        ax.set_ylabel("force on wall [N]")
        ax.legend(fontsize=7, ncol=2)
        ax.grid(alpha=0.3)
        fig.tight_layout()
        written.append(os.path.join(out, "wall_forces.png"))
        fig.savefig(written[-1], dpi=120)

    fig, ax = plt.subplots(figsize=(7, 4))
    n = [max(v, 1.0) for v in s["particles"]]
    ax.plot(t, [2 * c / k for c, k in zip(s["pair_contacts"], n)])
    ax.set_xlabel("time [s]")
    ax.set_ylabel("contacts per particle")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    written.append(os.path.join(out, "contacts.png"))
    fig.savefig(written[-1], dpi=120)

    for p in written:
        print(p)


if __name__ == "__main__":
    main()
