#!/usr/bin/python3
"""Granular beam in 4-point bending (Götz 2024 §5.3, Figs. 26-29): stress over strain.

Usage: plot_beam_four_point.py OUT.png RUN_DIR [RUN_DIR ...]
Each RUN_DIR is a finished `talus run` of a `[beam] test = "four_point"` scenario. Left: σ(ε)
of each run (beam.csv) with its yield point Y_b (summary.json). Right: the small-strain part
ε <= 0.004 with the fitted line σ = E_b ε (fit over ε <= 0.002). The legend names the run and
its grains' friction at bending (μ_p). Prints the table it drew.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from talus_csv import read_columns  # noqa: E402


def read_run(run):
    with open(os.path.join(run, "summary.json")) as f:
        s = json.load(f)
    c = read_columns(os.path.join(run, "beam.csv"))
    t0 = s["beam"]["bending_start"]
    keep = [k for k, t in enumerate(c["time"]) if t >= t0]
    mats = {m["name"]: m for m in s["scenario"]["materials"]}
    grain = mats[s["scenario"]["particles"][0]["material"]]
    return {"run": os.path.basename(os.path.normpath(run)), "b": s["beam"],
            "mu_init": grain["friction"], "eps": [c["strain"][k] for k in keep],
            "sigma": [c["stress"][k] for k in keep]}


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, runs = sys.argv[1], [read_run(r) for r in sys.argv[2:]]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4))
    print("run  mu_init  mu_p  E_b [MPa]  fit points  r2  Y_b [kPa]  eps_Y  largest eps")
    for k, r in enumerate(runs):
        b, c = r["b"], f"C{k}"
        mu_p = b.get("bending_friction", r["mu_init"])
        label = f"{r['run']} (μ_init {r['mu_init']:g}, μ_p {mu_p:g})"
        ax.plot(r["eps"], [1e-3 * s for s in r["sigma"]], color=c, lw=0.8, label=label)
        small = [(e, s) for e, s in zip(r["eps"], r["sigma"]) if e <= 0.004]
        bx.plot([e for e, _ in small], [1e-3 * s for _, s in small], color=c, lw=0.8)
        e_b = b.get("youngs_modulus")
        if e_b:
            bx.plot([0, 0.002], [0, 1e-3 * e_b * 0.002], "--", color=c, lw=1.2,
                    label=f"E_b = {1e-6 * e_b:.2f} MPa")
        if b.get("yield_found"):
            ax.plot([b["yield_strain"]], [1e-3 * b["yield_strength"]], "o", color=c, ms=6)
        print(f"{r['run']}  {r['mu_init']:g}  {mu_p:g}  "
              f"{1e-6 * e_b if e_b else float('nan'):.3f}  {b.get('fit_points', 0)}  "
              f"{b.get('fit_r2', float('nan')):.4f}  "
              f"{1e-3 * b['yield_strength'] if b.get('yield_found') else float('nan'):.2f}  "
              f"{b.get('yield_strain', float('nan')):.4f}  {b.get('largest_strain', 0):.4f}")
    ax.set_xlabel(r"strain $\epsilon = 108 h \Delta z / (23 L^2)$")
    ax.set_ylabel(r"stress $\sigma = F L / (h^2 t)$ [kPa]")
    ax.set_title("dots: yield strength Y_b")
    bx.set_xlabel(r"strain $\epsilon$")
    bx.set_ylabel(r"stress $\sigma$ [kPa]")
    bx.set_title(r"small strains; dashed: fit over $\epsilon \leq 0.002$")
    for a in (ax, bx):
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
