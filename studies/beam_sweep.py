#!/usr/bin/python3
"""The granular beam's modulus over grain modulus, membrane modulus and vacuum, and the fit
of Götz's collapse law (2024 §5.2, eq. 39):

Feeds docs/validation/membranes-and-jamming.md, section "Granular beam (Götz 2024 §5.2;
...)": the sweep of the moduli and the fit of the collapse law.

    E_b,eff / E_p,eff = e^alpha (E_m,eff / E_p,eff)^beta (p / E_p,eff)^gamma,

E_eff = E / (1 - nu^2) for grains (nu_p = 0.245) and membrane (nu_m = 1/3); the source
found alpha = 0.29, beta = 0.41, gamma = 0.36.

Usage: beam_sweep.py TALUS SCENARIO OUT_DIR --ep 5e6,2e7,1e8 --em 1e7,1e8,1e9
                     --p 3e4,6e4,9e4 [-j N] [--plot OUT.png] [--set key=value ...]

Runs every (E_p, E_m, p) of SCENARIO (a [beam] scenario: materials 0 the grains, 1 the
membrane's contact material, membrane 0 the beam) with one thread each, N at a time, then
fits (alpha, beta, gamma) by least squares on the logarithms. Prints one line per run,
the fit and its root-mean-square residual, and writes OUT_DIR/sweep.csv; --plot draws
E_b,eff/E_p,eff against the source's law and against the fitted one (as the source's
Abb. 21). Runs already finished in OUT_DIR (a summary.json there) are read, not rerun.
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import subprocess

import numpy as np

NU_P, NU_M = 0.245, 1.0 / 3.0


def floats(text):
    return [float(v) for v in text.split(",")]


def run_one(a, ep, em, p):
    out = os.path.join(a.out, f"ep{ep:g}_em{em:g}_p{p:g}")
    sets = [f"materials.0.youngs_modulus={ep:g}", f"materials.1.youngs_modulus={em:g}",
            f"membranes.0.youngs_modulus={em:g}", f"membranes.0.pressure={-p:g}",
            "output.snapshots=false"] + a.set
    cmd = [a.talus, "run", a.scenario, "--out", out, "--force", "--quiet", "--threads", "1"]
    for s in sets:
        cmd += ["--set", s]
    if not os.path.exists(os.path.join(out, "summary.json")):
        subprocess.run(cmd, check=True)
    b = json.load(open(os.path.join(out, "summary.json")))["beam"]
    return {"E_p": ep, "E_m": em, "p": p, "E_b": b.get("youngs_modulus", float("nan")),
            "E_b_eff": b.get("effective_modulus", float("nan")), "r2": b.get("r2", float("nan")),
            "dz_max": b.get("deflection_at_max_load", float("nan")),
            "gap": b.get("largest_hysteresis_gap", float("nan"))}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("talus")
    ap.add_argument("scenario")
    ap.add_argument("out")
    ap.add_argument("--ep", type=floats, required=True)
    ap.add_argument("--em", type=floats, required=True)
    ap.add_argument("--p", type=floats, required=True)
    ap.add_argument("-j", type=int, default=1)
    ap.add_argument("--plot")
    ap.add_argument("--set", action="append", default=[])
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    combos = [(ep, em, p) for ep in a.ep for em in a.em for p in a.p]
    with concurrent.futures.ThreadPoolExecutor(a.j) as pool:
        rows = list(pool.map(lambda c: run_one(a, *c), combos))
    for r in rows:
        ep_eff, em_eff = r["E_p"] / (1 - NU_P**2), r["E_m"] / (1 - NU_M**2)
        r["x_m"] = math.log(em_eff / ep_eff)
        r["x_p"] = math.log(r["p"] / ep_eff)
        r["y"] = math.log(r["E_b_eff"] / ep_eff)
        r["source"] = ep_eff * math.exp(0.29 + 0.41 * r["x_m"] + 0.36 * r["x_p"])
    keys = ["E_p", "E_m", "p", "E_b", "E_b_eff", "source", "r2", "dz_max", "gap"]
    with open(os.path.join(a.out, "sweep.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    print("| E_p [MPa] | E_m [MPa] | p [kPa] | E_b,eff [MPa] | source law [MPa] | r^2 | dz(F_max) [um] | load/unload gap [um] |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['E_p'] / 1e6:g} | {r['E_m'] / 1e6:g} | {r['p'] / 1e3:g} | {r['E_b_eff'] / 1e6:.3f} | "
              f"{r['source'] / 1e6:.3f} | {r['r2']:.4f} | {1e6 * r['dz_max']:.2f} | {1e6 * r['gap']:.2f} |")
    A = np.array([[1.0, r["x_m"], r["x_p"]] for r in rows])
    y = np.array([r["y"] for r in rows])
    coef, *_ = np.linalg.lstsq(A, y, rcond=None)
    res = y - A @ coef
    src = y - A @ np.array([0.29, 0.41, 0.36])
    print(f"fit: alpha = {coef[0]:.3f}, beta = {coef[1]:.3f}, gamma = {coef[2]:.3f} "
          f"(source 0.29, 0.41, 0.36); rms residual of ln(E_b,eff/E_p,eff): fit {np.sqrt(np.mean(res**2)):.3f}, "
          f"source law {np.sqrt(np.mean(src**2)):.3f}")
    if a.plot:
        plot(a.plot, A, y, coef)


def plot(out, A, y, coef):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    for ax, c, label in ((axes[0], np.array([0.29, 0.41, 0.36]), "source"),
                         (axes[1], coef, "fitted here")):
        x = A @ c
        ax.scatter(np.exp(x), np.exp(y), s=14)
        lim = [np.exp(min(x.min(), y.min())) * 0.8, np.exp(max(x.max(), y.max())) * 1.25]
        ax.plot(lim, lim, "k-", lw=0.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(rf"$e^{{{c[0]:.2f}}}(E_m^{{eff}}/E_p^{{eff}})^{{{c[1]:.2f}}}"
                      rf"(p/E_p^{{eff}})^{{{c[2]:.2f}}}$ ({label})")
        ax.set_ylabel(r"$E_b^{eff}/E_p^{eff}$ (runs)")
        ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
