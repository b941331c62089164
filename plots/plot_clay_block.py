#!/usr/bin/python3
"""Cracks of a clay block run (scenarios/mpm/mpm_clay_block*.toml; van den Bout §3).

Usage: plot_clay_block.py RUN_DIR [--corner-z Z] [--band B]
Writes RUN_DIR/plots/cracks.png and RUN_DIR/cracks.json and prints their paths.

The crack indicator is c/c0 of every material point (mpm.md: a crack is where
c/c0 < 1, and only a point that lost cohesion can be a physical crack). The
pattern is read in the block's reference configuration (each point at its
first-snapshot position, matched by id), seen from above (x down the slope,
z across; a 2D plan-view run's y is its across), so that "a crack from the obstacle corner along the flow direction
over half the block's length" becomes a length that can be measured:
  crack_length   along the band of initial z within B of the obstacle corner
                 line z = Z: the length, from the block's front backwards, over
                 which every slice of one point spacing holds a damaged point
                 (c/c0 < 0.5); as a fraction of the block's length too;
  damaged_rear   the fraction of damaged points that started in the rear half
                 of the block (away from the impact);
  damage_reach   how far back from the front 95 % of the damaged points
                 started, as a fraction of the block's length (local damage
                 near the impact: small; damage back to mid-length: about 0.5);
  cracked/damaged fractions of all points (c/c0 < 1, c/c0 < 0.5);
  broken_*       crack length, reach and fraction with the stricter c/c0 < 0.1
                 (nine tenths of the bonds gone), which tells a crack through
                 which the bonds are gone from a zone that is only weakened.
"""
import argparse
import json
import os

import matplotlib
from plot_mpm import read_points, snapshots

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DAMAGED = 0.5
BROKEN = 0.1


def crack_length(x0, damaged, spacing, corner_z, band, front):
    """Length from the front backwards over which every slice of one point
    spacing in the band about the corner line holds a damaged point."""
    in_band = np.abs(x0[:, 2] - corner_z) <= band
    slices = np.floor((front - x0[:, 0]) / spacing + 0.5).astype(int)
    crack = 0
    for k in range(int(np.max(slices)) + 1):
        if not np.any(damaged[in_band & (slices == k)]):
            break
        crack += 1
    return crack * spacing


def reach(x0, damaged, spacing, front, length):
    if not np.any(damaged):
        return 0.0
    return float(np.percentile(front - x0[damaged, 0], 95.0) + 0.5 * spacing) / length


def crack_metrics(x0, ratio, spacing, corner_z, band):
    front, rear = float(np.max(x0[:, 0])), float(np.min(x0[:, 0]))
    length = front - rear + spacing
    damaged = ratio < DAMAGED
    broken = ratio < BROKEN
    crack = crack_length(x0, damaged, spacing, corner_z, band, front)
    broken_crack = crack_length(x0, broken, spacing, corner_z, band, front)
    mid = rear + 0.5 * (front - rear)
    n_damaged = int(np.count_nonzero(damaged))
    return {
        "points": int(len(ratio)),
        "cracked_fraction": float(np.mean(ratio < 1.0)),
        "damaged_fraction": float(np.mean(damaged)),
        "min_c_over_c0": float(np.min(ratio)),
        "block_length": length,
        "corner_z": corner_z,
        "band_half_width": band,
        "crack_length": crack,
        "crack_length_fraction": crack / length,
        "damaged_rear_fraction":
            float(np.count_nonzero(damaged & (x0[:, 0] < mid)) / n_damaged) if n_damaged else 0.0,
        "damage_reach_fraction": reach(x0, damaged, spacing, front, length),
        "broken_fraction": float(np.mean(broken)),
        "broken_crack_length_fraction": broken_crack / length,
        "broken_reach_fraction": reach(x0, broken, spacing, front, length),
    }


def start_and_end(run, fields):
    """Each point's first-snapshot position (matched by id), its last position, the first and
    last snapshots' fields (the first in its own order) and the last snapshot's time."""
    snaps = snapshots(run)
    if len(snaps) < 2:
        raise SystemExit(f"{run}: needs at least two particle snapshots")
    xyz0, d0 = read_points(snaps[0][1], ("id",) + tuple(fields))
    xyz1, d1 = read_points(snaps[-1][1], ("id",) + tuple(fields))
    start = np.empty((int(np.max(d0["id"])) + 1, 3))
    start[d0["id"].astype(int)] = xyz0
    return start[d1["id"].astype(int)], xyz1, d0, d1, snaps[-1][0]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    ap.add_argument("--corner-z", type=float, default=0.275,
                    help="z of the obstacle's corner line (m; default: the bundled scenario's)")
    ap.add_argument("--band", type=float, default=None,
                    help="half width of the band about the corner line (m; default: one spacing)")
    args = ap.parse_args()
    x0, x1, _, d1, t_end = start_and_end(args.run, ("c_over_c0", "radius", "plastic_strain"))
    # A 2D plan-view run (z = 0 everywhere): its y is across; no side view.
    plan = not np.any(x0[:, 2])
    if plan:
        x0, x1 = x0[:, [0, 2, 1]], x1[:, [0, 2, 1]]
    ratio = d1["c_over_c0"]
    spacing = 2.0 * float(np.median(d1["radius"]))
    band = args.band if args.band is not None else spacing
    m = crack_metrics(x0, ratio, spacing, args.corner_z, band)
    m["time"] = t_end

    out = os.path.join(args.run, "plots")
    os.makedirs(out, exist_ok=True)
    views = ((0, 2, "z0 across (m)"),) if plan else (
        (0, 2, "z0 across (m)"), (0, 1, "y0 above the bed (m)"))
    fig, ax = plt.subplots(1, len(views) + 1, figsize=(5 * len(views) + 5, 4.5))
    # Reference configuration, seen from above and from the side: the mean
    # c/c0 over each column of points (a crack through the height shows as a
    # low column; damage at the base alone only halves it).
    for k, (a, b, label) in enumerate(views):
        cols = {}
        for key, r in zip(map(tuple, np.round(x0[:, [a, b]] / spacing).astype(int)), ratio):
            cols.setdefault(key, []).append(r)
        keys = np.array(list(cols))
        sc = ax[k].scatter(keys[:, 0] * spacing, keys[:, 1] * spacing,
                           c=[np.mean(v) for v in cols.values()], cmap="RdYlBu", vmin=0, vmax=1,
                           s=40, marker="s")
        ax[k].set(xlabel="x0 down the slope (m)", ylabel=label, aspect="equal")
    ax[0].axhline(args.corner_z, color="k", lw=0.8, ls="--")
    ax[0].set_title("start shape from above, mean c/c0")
    if not plan:
        ax[1].set_title("start shape from the side, mean c/c0")
    top = np.argsort(x1[:, 1])
    ax[-1].scatter(x1[top, 0], x1[top, 2], c=ratio[top], cmap="RdYlBu", vmin=0, vmax=1, s=4)
    ax[-1].set(title=f"t = {m['time']:.2f} s, seen from above", xlabel="x down the slope (m)",
              ylabel="z across (m)", aspect="equal")
    fig.colorbar(sc, ax=ax, label="c / c0 (crack where < 1)")
    png = os.path.join(out, "cracks.png")
    fig.savefig(png, dpi=120)
    path = os.path.join(args.run, "cracks.json")
    with open(path, "w") as f:
        json.dump(m, f, indent=2)
    print(png)
    print(path)


if __name__ == "__main__":
    main()
