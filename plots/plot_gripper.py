#!/usr/bin/python3
"""Granular gripper (Götz 2024 §4.2, Figs. 11 and 12): force on the object and holding force.

Usage: plot_gripper.py OUT.png RUN_DIR [RUN_DIR ...]
Each RUN_DIR is a finished `talus run` of scenarios/dem/granular_gripper*.toml (one grain
Young's modulus E_p each, e.g. --set materials.0.youngs_modulus=5e6). Left: the vertical
force of the membrane on the object over time from gripper.csv (negative while it is
pushed in, positive while the membrane holds it back during the pull), phases marked for
the first run. Right: the holding force F_h (summary.json, the largest upward force during
the pull) over E_p on a log axis, one line per gripper radius. Prints the table it drew.
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PHASES = ["fill", "settle", "push", "relax", "vacuum", "hold", "pull"]


def read_run(run):
    with open(os.path.join(run, "summary.json")) as f:
        s = json.load(f)
    sc = s["scenario"]
    material = sc["particles"][0]["material"]
    e_p = next(m["youngs_modulus"] for m in sc["materials"] if m["name"] == material)
    with open(os.path.join(run, "gripper.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    membrane = next(m for m in sc["membranes"] if m["name"] == sc["gripper"]["membrane"])
    return {"run": os.path.basename(os.path.normpath(run)), "E_p": e_p,
            "R": membrane["radius"], "g": s["gripper"], "rows": rows}


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, runs = sys.argv[1], sorted((read_run(r) for r in sys.argv[2:]), key=lambda r: r["E_p"])
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4))
    for r in runs:
        ax.plot([q["time"] for q in r["rows"]], [q["force_z"] for q in r["rows"]], lw=0.8,
                label=f"R = {1e3 * r['R']:g} mm, E_p = {r['E_p']:.3g} Pa")
    g = runs[0]["g"]
    for t in ("push_start", "push_end", "vacuum_start", "vacuum_end", "pull_start"):
        ax.axvline(g[t], color="0.6", lw=0.6, ls=":")
    ax.set_xlabel("time [s]")
    ax.set_ylabel(r"force of the membrane on the object $F_z$ [N]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    print("run  R [mm]  E_p [Pa]  F_h [N]  max push force [N]  F_z before pull [N]  final contacts")
    for r in runs:
        s = r["g"]
        print(f"{r['run']}  {1e3 * r['R']:g}  {r['E_p']:.3g}  {s['holding_force']:.3f}  "
              f"{s['max_push_force']:.3f}  {s['force_before_pull']:.3f}  "
              f"{s['final_object_contacts']}")
    for k, radius in enumerate(sorted({r["R"] for r in runs})):
        pts = [r for r in runs if r["R"] == radius]
        bx.plot([r["E_p"] for r in pts], [r["g"]["holding_force"] for r in pts], "os^"[k % 3] + "-",
                lw=1, label=f"gripper R = {1e3 * radius:g} mm")
    bx.legend(fontsize=7)
    bx.set_xscale("log")
    bx.set_xlabel(r"grain Young's modulus $E_p$ [Pa]")
    bx.set_ylabel(r"holding force $F_h$ [N]")
    bx.set_ylim(bottom=0)
    bx.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
