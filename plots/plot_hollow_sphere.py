#!/usr/bin/python3
"""Pressure on the hollow sphere's object versus grain stiffness (Götz 2024 §4.3, Fig. 14).

Usage: plot_hollow_sphere.py OUT.png RUN_DIR [RUN_DIR ...]
Each RUN_DIR is a finished `talus run` of scenarios/dem/hollow_sphere*.toml (one grain
Young's modulus E_p each, e.g. --set materials.0.youngs_modulus=5e6). From its
summary.json it takes E_p (the first [[particles]] source's material), the plateau
p_obj and the continuum value of eq. (33); it draws p_obj / p_vac over E_p (log axis)
with the continuum value as a dashed line (one per distinct geometry), and prints the
table it drew. Runs of different geometries get different markers.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_run(run):
    with open(os.path.join(run, "summary.json")) as f:
        s = json.load(f)
    sc = s["scenario"]
    material = sc["particles"][0]["material"]
    e_p = next(m["youngs_modulus"] for m in sc["materials"] if m["name"] == material)
    h = s["hollow_sphere"]
    if "p_obj_plateau" not in h:
        sys.exit(f"{run}: no plateau in summary.json (did the run pass the vacuum ramp?)")
    return {
        "run": os.path.basename(os.path.normpath(run)),
        "E_p": e_p,
        "p_vac": h["p_vac"],
        "p_obj": h["p_obj_plateau"],
        "continuum": h["p_obj_continuum"],
        "geometry": (h["object_radius"], h["shell_radius"]),
        "shell_final": h.get("shell_radius_final", float("nan")),
    }


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, runs = sys.argv[1], [read_run(r) for r in sys.argv[2:]]
    fig, ax = plt.subplots(figsize=(6, 4))
    markers = "osd^v"
    geometries = sorted({r["geometry"] for r in runs})
    print("run  E_p [Pa]  p_obj [kPa]  p_obj/p_vac  continuum/p_vac  shell radius [mm]")
    for k, g in enumerate(geometries):
        pts = sorted((r for r in runs if r["geometry"] == g), key=lambda r: r["E_p"])
        label = f"R_obj = {1e3 * g[0]:g} mm, R_out = {1e3 * g[1]:g} mm"
        ax.plot([r["E_p"] for r in pts], [r["p_obj"] / r["p_vac"] for r in pts],
                marker=markers[k % len(markers)], lw=1, label=f"DEM, {label}")
        ax.axhline(pts[0]["continuum"] / pts[0]["p_vac"], ls="--", lw=1, color=f"C{k}",
                   label=f"continuum eq. (33), {label}")
        for r in pts:
            print(f"{r['run']}  {r['E_p']:.3g}  {r['p_obj'] / 1e3:.1f}  "
                  f"{r['p_obj'] / r['p_vac']:.3f}  {r['continuum'] / r['p_vac']:.3f}  "
                  f"{1e3 * r['shell_final']:.2f}")
    ax.set_xscale("log")
    ax.set_xlabel(r"grain Young's modulus $E_p$ [Pa]")
    ax.set_ylabel(r"$p_{obj} / p_{vac}$")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
