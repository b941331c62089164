#!/usr/bin/python3
"""The granular beam in 4-point bending over the grains' friction, protocols A and B
(Götz 2024 §5.3.3, Figs. 27-29, Table 8), and the fit of the source's eq. 46

Feeds docs/validation/membranes-and-jamming.md, section "Granular beam, 4-point bending
(Götz 2024 §5.3; ...)": the friction sweep and the fit of eq. 46.

    Y_b(mu_p) = (Y0 - Yinf) exp(-a mu_p) + Yinf

per protocol. Protocol A: the grains' friction during the vacuum (mu_init) is mu_p;
protocol B: mu_init = 0.3 (and mu_p >= 0.3).

Usage: beam_four_point_sweep.py TALUS SCENARIO OUT_DIR --mu 0,0.3,0.6,1.2 [--protocols A,B]
                                [--seeds 5] [-j N] [--plot OUT.png] [--set key=value ...]

Runs SCENARIO (a four-point [beam] scenario whose materials 0 are the grains) for each
protocol, mu_p and seed with one thread each, N at a time. Prints one line per run (E_b,
Y_b, the largest stress and strain), the fit of eq. 46 per protocol over the seeds' mean Y_b
and, beside it, over their mean largest stress (a by a grid search, Y0 and Yinf by least
squares at each a), and writes OUT_DIR/sweep.csv; --plot draws E_b, Y_b and the largest
stress over mu_p (as the source's Abb. 29). Runs already finished in OUT_DIR
(a summary.json there) are read, not rerun.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import subprocess

import numpy as np

MU_B = 0.3  # protocol B's mu_init (source §5.3.3)


def floats(text):
    return [float(v) for v in text.split(",")]


def run_one(a, protocol, mu, seed):
    mu_init = mu if protocol == "A" else MU_B
    out = os.path.join(a.out, f"{protocol}_mu{mu:g}_seed{seed}")
    sets = [f"materials.0.friction={mu_init:g}", f"beam.bending_friction={mu:g}",
            f"run.seed={seed}", "output.snapshots=false"] + a.set
    cmd = [a.talus, "run", a.scenario, "--out", out, "--force", "--quiet", "--threads", "1"]
    for s in sets:
        cmd += ["--set", s]
    if not os.path.exists(os.path.join(out, "summary.json")):
        subprocess.run(cmd, check=True)
    b = json.load(open(os.path.join(out, "summary.json")))["beam"]
    nan = float("nan")
    return {"protocol": protocol, "mu_init": mu_init, "mu_p": mu, "seed": seed,
            "E_b": b.get("youngs_modulus", nan), "r2": b.get("fit_r2", nan),
            "Y_b": b["yield_strength"] if b.get("yield_found") else nan,
            "eps_Y": b["yield_strain"] if b.get("yield_found") else nan,
            "sigma_max": b.get("largest_stress", nan), "largest_strain": b.get("largest_strain", nan),
            "E_b_nominal": b.get("youngs_modulus_nominal", nan),
            "Y_b_nominal": b.get("yield_strength_nominal", nan)}


def fit_eq46(mu, y):
    """(Y0, Yinf, a) minimising the squared residual; None with fewer than 4 points (three
    parameters through three points say nothing: protocol B over 0.3, 0.6, 1.2 gave Y0 < 0)."""
    mu, y = np.asarray(mu), np.asarray(y)
    if len(mu) < 4:
        return None
    best = None
    for a in np.geomspace(0.05, 500, 2000):
        e = np.exp(-a * mu)
        A = np.column_stack([e, 1 - e])  # Y = Y0 e + Yinf (1 - e)
        coef, *_ = np.linalg.lstsq(A, y, rcond=None)
        r = float(np.sum((A @ coef - y) ** 2))
        if best is None or r < best[0]:
            best = (r, coef[0], coef[1], a)
    return best[1], best[2], best[3]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("talus")
    ap.add_argument("scenario")
    ap.add_argument("out")
    ap.add_argument("--mu", type=floats, required=True)
    ap.add_argument("--protocols", default="A,B")
    ap.add_argument("--seeds", default="5")
    ap.add_argument("-j", type=int, default=1)
    ap.add_argument("--plot")
    ap.add_argument("--set", action="append", default=[])
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    seeds = [int(s) for s in a.seeds.split(",")]
    combos = [(p, mu, s) for p in a.protocols.split(",") for mu in a.mu for s in seeds
              if p == "A" or mu >= MU_B]  # B excludes mu_p < mu_init (source)
    with concurrent.futures.ThreadPoolExecutor(a.j) as pool:
        rows = list(pool.map(lambda c: run_one(a, *c), combos))
    keys = ["protocol", "mu_init", "mu_p", "seed", "E_b", "r2", "Y_b", "eps_Y", "sigma_max", "largest_strain",
            "E_b_nominal", "Y_b_nominal"]
    with open(os.path.join(a.out, "sweep.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    print("| protocol | mu_init | mu_p | seed | E_b [MPa] | fit r^2 | Y_b [kPa] | eps at Y_b | largest sigma [kPa] | "
          "largest eps | E_b, Y_b with the rest size [MPa, kPa] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['protocol']} | {r['mu_init']:g} | {r['mu_p']:g} | {r['seed']} | {r['E_b'] / 1e6:.3f} | "
              f"{r['r2']:.3f} | {r['Y_b'] / 1e3:.2f} | {r['eps_Y']:.4f} | {r['sigma_max'] / 1e3:.2f} | "
              f"{r['largest_strain']:.4f} | {r['E_b_nominal'] / 1e6:.3f}, {r['Y_b_nominal'] / 1e3:.2f} |")
    fits = {}
    for key in ("Y_b", "sigma_max"):
        for p in a.protocols.split(","):
            mus = sorted({r["mu_p"] for r in rows if r["protocol"] == p})
            ys = []
            for m in mus:
                found = [r[key] for r in rows if r["protocol"] == p and r["mu_p"] == m and np.isfinite(r[key])]
                ys.append(np.mean(found) if found else float("nan"))
            ok = [(m, y) for m, y in zip(mus, ys) if np.isfinite(y)]
            fit = fit_eq46([m for m, _ in ok], [y for _, y in ok])
            fits[key, p] = (mus, ys, fit)
            if fit:
                print(f"eq. 46 on {key}, protocol {p} ({len(ok)} friction values): Y0 = {fit[0] / 1e3:.2f} kPa, "
                      f"Yinf = {fit[1] / 1e3:.2f} kPa, a = {fit[2]:.2f} "
                      f"(source Y_b, E_p = 100 MPa: A 20.63, 96.15, 6.67; B 35.65, 119.41, 2.85)")
            else:
                print(f"eq. 46 on {key}, protocol {p}: fewer than 4 friction values with a value, no fit")
    if a.plot:
        plot(a.plot, rows, fits)


def plot(out, rows, fits):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(15, 4))
    protocols = sorted({p for _, p in fits})
    for k, p in enumerate(protocols):
        c, mine = f"C{k}", [r for r in rows if r["protocol"] == p]
        axes[0].plot([r["mu_p"] for r in mine], [r["E_b"] / 1e6 for r in mine], "o", color=c, label=f"protocol {p}")
        for ax, key in ((axes[1], "Y_b"), (axes[2], "sigma_max")):
            ax.plot([r["mu_p"] for r in mine], [r[key] / 1e3 for r in mine], "o", color=c, label=f"protocol {p}")
            mus, _, fit = fits[key, p]
            if fit:
                m = np.linspace(0, max(mus), 100)
                ax.plot(m, ((fit[0] - fit[1]) * np.exp(-fit[2] * m) + fit[1]) / 1e3, "-", color=c, lw=0.8,
                        label=f"eq. 46: {fit[0] / 1e3:.0f}, {fit[1] / 1e3:.0f} kPa, a {fit[2]:.2f}")
    axes[0].set_ylabel(r"$E_b$ [MPa] (fit over $\epsilon \leq 0.002$)")
    axes[1].set_ylabel(r"yield strength $Y_b$ [kPa] (curvature turns positive)")
    axes[2].set_ylabel(r"largest stress $\sigma_{max}$ [kPa]")
    for x in axes:
        x.set_xlabel(r"grain friction at bending $\mu_p$")
        x.grid(alpha=0.3)
        x.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
