#!/usr/bin/python3
"""Deviator stress versus axial strain of triaxial runs (Götz 2024 §3.3.1).

Usage: plot_triaxial.py OUT.png RUN_DIR [RUN_DIR ...]
Reads RUN_DIR/triaxial.csv of each run (talus run of scenarios/dem/triaxial_*.toml)
and draws sigma_d = p_plates - p_c over eps = ln(h0/h) for the loading phase
(phase = 1), one curve per run labelled with the run folder's name. With two
or more runs it also prints, on a common eps grid, the spread (max - min) of
sigma_d between the runs, in kPa: its mean and its largest value.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from talus_csv import read_columns  # noqa: E402


def loading_curve(run):
    c = read_columns(os.path.join(run, "triaxial.csv"))
    keep = [k for k, ph in enumerate(c["phase"]) if ph == 1.0]
    return [c["eps"][k] for k in keep], [c["sigma_d"][k] / 1e3 for k in keep]


def interpolate(xs, ys, x):
    for k in range(1, len(xs)):
        if xs[k - 1] <= x <= xs[k] and xs[k] > xs[k - 1]:
            t = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
            return ys[k - 1] + t * (ys[k] - ys[k - 1])
    return None


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, runs = sys.argv[1], sys.argv[2:]
    curves = {os.path.basename(os.path.normpath(r)): loading_curve(r) for r in runs}
    fig, ax = plt.subplots(figsize=(6, 4))
    for name, (eps, sig) in curves.items():
        ax.plot(eps, sig, label=name, lw=1)
    ax.set_xlabel(r"axial strain $\epsilon = \ln(h_0/h)$")
    ax.set_ylabel(r"deviator stress $\sigma_d = p_{plates} - p_c$ [kPa]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)
    if len(curves) >= 2:
        eps_max = min(max(e) for e, _ in curves.values() if e)
        grid = [eps_max * k / 50 for k in range(51)]
        spreads = []
        for x in grid:
            vals = [interpolate(e, s, x) for e, s in curves.values()]
            if all(v is not None for v in vals):
                spreads.append(max(vals) - min(vals))
        if spreads:
            print(f"eps 0..{eps_max:.4f}: spread of sigma_d between runs: mean "
                  f"{sum(spreads) / len(spreads):.1f} kPa, largest {max(spreads):.1f} kPa")
    for name, (eps, sig) in curves.items():
        if sig:
            k = max(range(len(sig)), key=lambda i: sig[i])
            print(f"{name}: eps reached {eps[-1]:.4f}, peak sigma_d {sig[k]:.1f} kPa "
                  f"at eps {eps[k]:.4f}")


if __name__ == "__main__":
    main()
