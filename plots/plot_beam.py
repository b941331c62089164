#!/usr/bin/python3
"""Granular beam in 3-point bending (Götz 2024 §5.2, Figs. 18 and 19): deflection over load.

Usage: plot_beam.py OUT.png RUN_DIR [RUN_DIR ...]
Each RUN_DIR is a finished `talus run` of scenarios/dem/granular_beam_3pt*.toml. Left: the
deflection at the bottom centre over time with the load (beam.csv). Right: the deflection
of each load step (beam_steps.csv, mean over the second half of the step) over the load,
dots loading and crosses unloading as in the source, and the line of the Timoshenko fit
(summary.json). Prints the table it drew.
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_run(run):
    with open(os.path.join(run, "summary.json")) as f:
        s = json.load(f)
    rows = {}
    for name in ("beam.csv", "beam_steps.csv"):
        with open(os.path.join(run, name)) as f:
            rows[name] = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    return {"run": os.path.basename(os.path.normpath(run)), "b": s["beam"], "series": rows["beam.csv"],
            "steps": rows["beam_steps.csv"], "params": s["scenario"]["beam"]}


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, runs = sys.argv[1], [read_run(r) for r in sys.argv[2:]]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4))
    for r in runs:
        rows = [q for q in r["series"] if q["step"] >= 0]
        z0 = r["steps"][0]["bottom_centre_z"]
        ax.plot([q["time"] for q in rows], [1e3 * (z0 - q["bottom_centre_z"]) for q in rows], lw=0.8,
                label=f"{r['run']}: deflection")
    ax2 = ax.twinx()
    rows = [q for q in runs[0]["series"] if q["step"] >= 0]
    ax2.plot([q["time"] for q in rows], [q["load"] for q in rows], color="0.5", lw=0.8, ls="--")
    ax2.set_ylabel("load F [N] (dashed)")
    ax.set_xlabel("time [s]")
    ax.set_ylabel(r"deflection $\Delta z$ [mm]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    print("run  span [m]  width [m]  height [m]  dz(F_max) [mm]  E_b [MPa]  E_b,eff [MPa]  r2  "
          "largest loading/unloading gap [mm]")
    for k, r in enumerate(runs):
        n = len(r["steps"]) // 2
        up, down = r["steps"][:n + 1], r["steps"][n:]
        c = f"C{k}"
        bx.plot([q["load"] for q in up], [1e3 * q["deflection"] for q in up], "o", color=c, ms=4,
                label=f"{r['run']} loading")
        bx.plot([q["load"] for q in down], [1e3 * q["deflection"] for q in down], "x", color=c, ms=5,
                label="unloading")
        b = r["b"]
        if "slope_m_per_N" in b:
            f = [0, r["params"]["max_load"]]
            bx.plot(f, [1e3 * (b["intercept_m"] + b["slope_m_per_N"] * x) for x in f], "-", color=c,
                    lw=0.8, label=f"fit: E_b,eff = {1e-6 * b['effective_modulus']:.2f} MPa")
            print(f"{r['run']}  {b['span']:.4f}  {b['width']:.4f}  {b['height']:.4f}  "
                  f"{1e3 * b['deflection_at_max_load']:.4f}  {1e-6 * b['youngs_modulus']:.3f}  "
                  f"{1e-6 * b['effective_modulus']:.3f}  {b['r2']:.5f}  "
                  f"{1e3 * b.get('largest_hysteresis_gap', float('nan')):.4f}")
    bx.set_xlabel("load F [N]")
    bx.set_ylabel(r"deflection $\Delta z$ [mm]")
    bx.grid(alpha=0.3)
    bx.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
