#!/usr/bin/python3
"""Plan-view clay blocks over cell sizes and impact speeds (docs/validation.md,
"Clay block against an obstacle", plan view).

Feeds docs/validation/mpm-clay-block.md, sections "Plan view (2D, ...)" and "A speed
sweep at ℓ = 2 cm".

Usage: clay_block_plan_sweep.py TALUS OUT --cells 0.01,0.0075 --speeds 0.7,1.0
                                [--set KEY=VALUE ...] [--eps-c E] [--jobs 2] [--label L]
Runs scenarios/mpm/mpm_clay_block_plan.toml (weak) and ..._strong.toml for every
cell size and speed (one thread each, --jobs at a time), reads each run's
crack metrics with plots/plot_clay_block.py (band = the cell size), prints a
markdown table and writes OUT/maps.png (OUT/maps_LABEL.png with --label): the mean c/c0 of each run in the
block's start shape, weak beside strong, one row per (cell, speed).
--eps-c E replaces the scenarios' cohesion loss by the local one with a fixed
critical volume strain E on every grid. Runs already
complete in OUT (a cracks.json present) are not repeated.
"""
import argparse
import concurrent.futures
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "plots"))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from plot_clay_block import start_and_end  # noqa: E402

CLAYS = {"weak": "mpm_clay_block_plan.toml", "strong": "mpm_clay_block_plan_strong.toml"}


def run_one(talus, out, clay, cell, speed, sets, label, eps_c):
    d = os.path.join(out, f"{label}{clay}_h{cell}_v{speed}")
    metrics = os.path.join(d, "cracks.json")
    if not os.path.exists(metrics):
        cmd = [talus, "run", os.path.join(ROOT, "scenarios", "mpm", CLAYS[clay]), "--out", d,
               "--force", "--quiet", "--threads", "1", "--set", f"grid.cell_size={cell}",
               "--set", f"bodies.0.velocity=[{speed},0.0]"]
        for s in sets:
            cmd += ["--set", s]
        if eps_c:
            cmd += ["--set", "materials.0.critical_opening=0", "--set",
                    "materials.0.nonlocal_length=0", "--set",
                    f"materials.0.critical_volume_strain={eps_c!r}"]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    # Metrics of a finished run are recomputed when plot_clay_block.py gained some.
    stale = True
    if os.path.exists(metrics):
        with open(metrics) as f:
            stale = "broken_fraction" not in json.load(f)
    if stale:
        subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "plots", "plot_clay_block.py"), d,
                        "--band", str(cell)], check=True, stdout=subprocess.DEVNULL)
    with open(metrics) as f:
        return d, json.load(f)


def start_map(ax, run):
    """c/c0 at the end, drawn in the start shape (x along, y across): the
    points start on a lattice of one spacing, so they fill an image."""
    x0, _, d0, d1, _ = start_and_end(run, ("c_over_c0", "radius"))
    spacing = 2.0 * float(np.median(d0["radius"]))
    lo = x0[:, :2].min(axis=0)
    idx = np.rint((x0[:, :2] - lo) / spacing).astype(int)
    image = np.full(idx.max(axis=0) + 1, np.nan)
    image[idx[:, 0], idx[:, 1]] = d1["c_over_c0"]
    hi = lo + idx.max(axis=0) * spacing
    return ax.imshow(image.T, origin="lower", cmap="RdYlBu", vmin=0, vmax=1,
                     extent=(lo[0] - spacing / 2, hi[0] + spacing / 2,
                             lo[1] - spacing / 2, hi[1] + spacing / 2))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("talus")
    ap.add_argument("out")
    ap.add_argument("--cells", required=True)
    ap.add_argument("--speeds", required=True)
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--label", default="")
    ap.add_argument("--eps-c", type=float, default=0.0)
    args = ap.parse_args()
    cells = args.cells.split(",")
    speeds = args.speeds.split(",")
    os.makedirs(args.out, exist_ok=True)
    jobs = [(clay, c, v) for c in cells for v in speeds for clay in CLAYS]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        done = list(pool.map(
            lambda j: run_one(args.talus, args.out, *j, args.set, args.label, args.eps_c), jobs))
    results = {j: r for j, r in zip(jobs, done)}
    print("| cell, v | clay | points | cracked | damaged | crack | reach "
          "| broken | broken crack | broken reach |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for c in cells:
        for v in speeds:
            for clay in CLAYS:
                m = results[(clay, c, v)][1]
                print(f"| {float(c) * 100:g} cm, {v} m/s | {clay} | {m['points']} | "
                      f"{m['cracked_fraction']:.3f} | {m['damaged_fraction']:.3f} | "
                      f"{m['crack_length_fraction']:.3f} | {m['damage_reach_fraction']:.3f} | "
                      f"{m['broken_fraction']:.3f} | {m['broken_crack_length_fraction']:.3f} | "
                      f"{m['broken_reach_fraction']:.3f} |")
    rows = [(c, v) for c in cells for v in speeds]
    fig, axes = plt.subplots(len(rows), 2, figsize=(8, 3.0 * len(rows)), squeeze=False,
                             layout="constrained")
    for k, (c, v) in enumerate(rows):
        for j, clay in enumerate(CLAYS):
            ax = axes[k][j]
            sc = start_map(ax, results[(clay, c, v)][0])
            ax.axhline(0.275, color="k", lw=0.6, ls="--")
            ax.set_title(f"{clay}, {float(c) * 100:g} cm, {v} m/s", fontsize=9)
            ax.tick_params(labelsize=7)
    fig.colorbar(sc, ax=axes, label="c / c0 at the end, in the start shape (x down, y across)",
                 shrink=0.5)
    png = os.path.join(args.out, f"maps_{args.label.strip('_')}.png" if args.label else "maps.png")
    fig.savefig(png, dpi=90)
    print(png)


if __name__ == "__main__":
    main()
