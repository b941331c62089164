#!/usr/bin/python3
"""The granular beam's force network during 4-point bending (Götz 2024 §5.3.4, Abb. 30).

Usage: plot_beam_force_network.py OUT.png RUN_DIR [RUN_DIR ...]
Each RUN_DIR is a finished `talus run` of a `[beam] test = "four_point"` scenario. Over the
bending stress σ: (a) the mean force per grain contact <F>, (b) its normal part <f_n> (solid,
left axis) and tangential part <|f_t|> (dashed, right axis), (c) the fraction of contacts within
5 % of the Coulomb limit; the dotted vertical line of each run is its yield strength Y_b when
the run found one. Prints the values at the start and at the largest stress.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from talus_csv import read_columns  # noqa: E402

KEYS = ("stress", "mean_contact_force", "mean_normal_force", "mean_tangential_force",
        "coulomb_fraction")


def read_run(run):
    with open(os.path.join(run, "summary.json")) as f:
        s = json.load(f)
    c = read_columns(os.path.join(run, "beam.csv"))
    keep = [k for k, t in enumerate(c["time"]) if t >= s["beam"]["bending_start"]]
    out = {key: [c[key][k] for k in keep] for key in KEYS}
    out["run"] = os.path.basename(os.path.normpath(run))
    out["beam"] = s["beam"]
    return out


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, runs = sys.argv[1], [read_run(r) for r in sys.argv[2:]]
    fig, (ax, bx, cx) = plt.subplots(1, 3, figsize=(15, 4))
    tx = bx.twinx()
    print("run  sigma[kPa]  <F>[N]  <f_n>[N]  <|f_t|>[N]  coulomb  (start -> largest stress)")
    for k, r in enumerate(runs):
        c, sigma = f"C{k}", [1e-3 * v for v in r["stress"]]
        mu_p = r["beam"].get("bending_friction")
        label = r["run"] + (f" (μ_p {mu_p:g})" if mu_p is not None else "")
        ax.plot(sigma, r["mean_contact_force"], color=c, lw=0.8, label=label)
        bx.plot(sigma, r["mean_normal_force"], color=c, lw=0.8)
        tx.plot(sigma, r["mean_tangential_force"], "--", color=c, lw=0.8)
        cx.plot(sigma, r["coulomb_fraction"], color=c, lw=0.8)
        if r["beam"].get("yield_found"):
            for a in (ax, bx, cx):
                a.axvline(1e-3 * r["beam"]["yield_strength"], color=c, ls=":", lw=0.8)
        top = max(range(len(sigma)), key=lambda i: sigma[i])
        for i in (0, top):
            print(f"{r['run']}  {sigma[i]:.1f}  {r['mean_contact_force'][i]:.4g}  "
                  f"{r['mean_normal_force'][i]:.4g}  {r['mean_tangential_force'][i]:.4g}  "
                  f"{r['coulomb_fraction'][i]:.3f}")
    ax.set_ylabel(r"$\langle F \rangle$ [N]")
    bx.set_ylabel(r"$\langle f_n \rangle$ [N] (solid)")
    tx.set_ylabel(r"$\langle |f_t| \rangle$ [N] (dashed)")
    cx.set_ylabel("contacts within 5 % of the Coulomb limit")
    for a, title in ((ax, "(a) mean force per contact"), (bx, "(b) normal and tangential"),
                     (cx, "(c) at the Coulomb limit")):
        a.set_xlabel(r"bending stress $\sigma$ [kPa]")
        a.set_title(title + "; dotted: Y_b", fontsize=9)
        a.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
