#!/usr/bin/python3
"""Velocity field of `talus analyse coarse-grain` (Götz 2024 ch. 6, Fig. 42c style).

Usage: plot_coarse_grain.py CG_DIR [TITLE] [VMAX]
(CG_DIR holds rz.csv, field.csv, coarse_grain.json; VMAX, in units of f d, fixes the colour and
arrow scale so that several runs compare; default: the largest speed of this field)
Writes CG_DIR/velocity_rz.png: (left) the azimuthal average in the r-z plane, drawn on both
sides of the axis as in a cut through it, (right) the x-z cut through the axis (middle y
layer of cells). Arrows: mean velocity over one period, relative to f d_mean; colour: solid
fraction. Uses Debian's matplotlib; run with /usr/bin/python3.
"""
import json
import os
import sys

import matplotlib
import numpy as np
from talus_csv import read_columns

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def side_vz(meta, f):
    """Mean v_z (mass-weighted, in units of f d) of the outer columns on the four sides, keyed
    "-x", "+x", "-y", "+y": the cells beyond 2/3 of the grid's half-width from the axis, within
    a band of 1/3 across. A flow tilted in x-z rises on one x side and sinks on the other."""
    scale = meta["period"] / meta["mean_diameter"]
    ax_x, ax_y = meta["axis"]
    half = 0.5 * (meta["box"][3] - meta["box"][0])
    out = {}
    for name, u, v in (("x", f["x"] - ax_x, f["y"] - ax_y), ("y", f["y"] - ax_y, f["x"] - ax_x)):
        for sign in (-1, 1):
            sel = (sign * u > 2 * half / 3) & (np.abs(v) < half / 3)
            vz = np.sum(f["mass_density"][sel] * f["vz"][sel]) / np.sum(f["mass_density"][sel])
            out[f"{'-+'[sign > 0]}{name}"] = float(vz * scale)
    return out


def main():
    cg = sys.argv[1]
    title = sys.argv[2] if len(sys.argv) > 2 else ""
    meta = json.load(open(os.path.join(cg, "coarse_grain.json")))
    scale = 1.0 / (meta["mean_diameter"] / meta["period"])  # velocities in units of f d
    rz = {k: np.array(v) for k, v in read_columns(os.path.join(cg, "rz.csv")).items()}
    f = {k: np.array(v) for k, v in read_columns(os.path.join(cg, "field.csv")).items()}
    nx, ny, nz = meta["cells"]
    ax_x, ax_y = meta["axis"]

    fig, axes = plt.subplots(1, 2, figsize=(9, 7.5), sharey=True)
    # Left: azimuthal average, mirrored to -r.
    r = np.concatenate([-rz["r"], rz["r"]]) * 1e3
    z = np.concatenate([rz["z"], rz["z"]]) * 1e3
    vr = np.concatenate([-rz["v_r"], rz["v_r"]]) * scale
    vz = np.concatenate([rz["v_z"], rz["v_z"]]) * scale
    phi = np.concatenate([rz["solid_fraction"], rz["solid_fraction"]])
    # Right: the middle layer of cells in y (the cut through the axis).
    j = int(np.argmin(np.abs(np.unique(f["y"]) - ax_y)))
    yj = np.unique(f["y"])[j]
    cut = np.isclose(f["y"], yj)
    panels = [
        (axes[0], r, z, vr, vz, phi, "azimuthal average, r [mm]"),
        (axes[1], (f["x"][cut] - ax_x) * 1e3, f["z"][cut] * 1e3, f["vx"][cut] * scale,
         f["vz"][cut] * scale, f["solid_fraction"][cut], f"x [mm] (cut y = {yj * 1e3:.2f} mm)"),
    ]
    vmax = max(np.max(np.hypot(p[3], p[4])) for p in panels) or 1.0
    if len(sys.argv) > 3:
        vmax = float(sys.argv[3])
    cell = np.min(np.diff(np.unique(f["x"]))) * 1e3 if nx > 1 else 1.0
    for ax, x, zz, u, w, c, label in panels:
        sc = ax.scatter(x, zz, c=c, s=70, marker="s", cmap="Greys", vmin=0, vmax=1.2, alpha=0.6)
        # The fastest arrow is 1.6 cells long.
        q = ax.quiver(x, zz, u, w, np.hypot(u, w), cmap="viridis", clim=(0, vmax), angles="xy",
                      scale=vmax / (1.6 * cell), scale_units="xy", width=0.008, pivot="middle")
        ax.set_xlabel(label)
        ax.set_aspect("equal")
    axes[0].set_ylabel("z [mm] (lab frame at the snapshots' phase)")
    fig.colorbar(q, ax=axes, label="|v| / (f d_mean)", shrink=0.6, location="right")
    fig.colorbar(sc, ax=axes, label="solid fraction", shrink=0.6, location="left")
    vz_axis = meta["axis_vz_normalised"]
    fig.suptitle(f"{title}\n{meta['intervals']} periods from t = {meta['first_time']:.3f} s; "
                 f"axis column v_z = {vz_axis:+.3f} f d, max |v| = "
                 f"{meta['max_speed_normalised']:.3f} f d, mass-weighted mean |v| = "
                 f"{meta['mean_speed_normalised']:.3f} f d\naxis column lower half "
                 f"{meta['axis_lower_vz_normalised']:+.3f} f d, upper half "
                 f"{meta['axis_upper_vz_normalised']:+.3f} f d", fontsize=10)
    for name, vz_side in side_vz(meta, f).items():
        print(f"side {name}: mean v_z = {vz_side:+.3f} f d")
    path = os.path.join(cg, "velocity_rz.png")
    fig.savefig(path, dpi=110)
    print(path)


if __name__ == "__main__":
    main()
