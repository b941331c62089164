#!/usr/bin/python3
"""Maps of the remaining strength fraction c/c0 of the hybrid clay-block study
(docs/validation/hybrid.md), in the particles' start shape (the plan-view MPM's pictures are in
the same frame), one panel per CSV written by build/tests/hybrid_clay_block.

Usage: clay_block_plot.py <out.png> <csv> [<csv> ...]   (titles from the file names)
Run with Debian's /usr/bin/python3 (matplotlib from python3-matplotlib).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    out, files = sys.argv[1], sys.argv[2:]
    cols = (len(files) + 1) // 2
    fig, axes = plt.subplots(2, cols, figsize=(3.6 * cols, 6.0), squeeze=False)
    for k, name in enumerate(files):
        ax = axes[k % 2][k // 2]
        rows = list(csv.DictReader(open(name)))
        x = [float(r["x0"]) for r in rows]
        y = [float(r["y0"]) for r in rows]
        f = [float(r["strength_fraction"]) for r in rows]
        size = 60000.0 / len(rows)
        sc = ax.scatter(x, y, c=f, s=size, cmap="RdYlBu", vmin=0, vmax=1, marker="s",
                        linewidths=0)
        ax.axhline(0.38, color="k", lw=0.5, ls="--")
        ax.set_aspect("equal")
        ax.set_title(os.path.splitext(os.path.basename(name))[0], fontsize=9)
        ax.tick_params(labelsize=7)
    fig.colorbar(sc, ax=axes, label="c / c0 at the end, in the start shape (x down, y across)")
    fig.savefig(out, dpi=90)


if __name__ == "__main__":
    main()
