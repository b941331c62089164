#!/usr/bin/python3
"""Aspect-ratio sweep of the MPM granular column collapse against Lube et al. (2005).

Runs scenarios/mpm/mpm_column_sweep.toml (L_i = 50 mm) for several a = H/L_i with
`talus run --set`, reads each run's summary.json and series.csv, prints a
Markdown table and writes a PNG of (L_inf - L_i)/L_i and H_inf/L_i against a
with Lube's planar laws: 1.2 a for a < 1.8, 1.9 a^(2/3) for a > 2.8, and
H_inf/L_i = a for a < 1.15.

Usage: mpm_column_sweep.py TALUS_EXE OUT_DIR PNG [--shape gimp|cubic_bspline] [--a 0.5,1,...]
Uses Debian's matplotlib; run with /usr/bin/python3.
"""
import argparse
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "plots"))
import matplotlib  # noqa: E402
from talus_csv import read_columns  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
WIDTH, CELL, PER_CELL = 0.05, 0.00625, 2


def lube(a):
    """Lube's planar run-out law, None between the two regimes."""
    if a <= 1.8:
        return 1.2 * a
    if a >= 2.8:
        return 1.9 * a ** (2.0 / 3.0)
    return None


def run(talus, out, a, shape):
    height = a * WIDTH
    duration = 0.3 + 3.0 * math.sqrt(height / 10.0)
    folder = os.path.join(out, f"{shape}_a{a:g}")
    reach = WIDTH * (1.0 + 1.5 * max(1.2 * a, 1.9 * a ** (2.0 / 3.0))) + 0.05
    cmd = [talus, "run", os.path.join(ROOT, "scenarios", "mpm", "mpm_column_sweep.toml"),
           "--out", folder, "--force", "--threads", "1",
           "--set", f"run.shape=\"{shape}\"",
           "--set", f"run.duration={duration:.3f}",
           "--set", f"grid.max=[{reach:.4f},{height + 0.02:.4f}]",
           "--set", f"bodies.0.box.max=[{WIDTH},{height:.5f}]"]
    subprocess.run(cmd, check=True, stderr=subprocess.DEVNULL)
    metrics = json.load(open(os.path.join(folder, "summary.json")))["metrics"]
    series = read_columns(os.path.join(folder, "series.csv"))
    half = 0.5 * CELL / PER_CELL  # the points' half spacing: front and top of the deposit
    return {"a": a, "folder": folder,
            "runout": (metrics["front_x_m"] + half - WIDTH) / WIDTH,
            "height": (metrics["top_m"] + half) / WIDTH,
            "ke_ratio": series["kinetic_energy"][-1] / max(series["kinetic_energy"]),
            "duration": duration}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("talus")
    ap.add_argument("out")
    ap.add_argument("png")
    ap.add_argument("--shape", default="gimp")
    ap.add_argument("--a", default="0.5,1,1.5,2,3,5,7")
    args = ap.parse_args()
    rows = [run(args.talus, args.out, float(a), args.shape) for a in args.a.split(",")]

    print(f"| a | (L∞ − L_i)/L_i | Lube | ratio | H∞/L_i | KE end/peak | t_end [s] |  ({args.shape})")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        law = lube(r["a"])
        print(f"| {r['a']:g} | {r['runout']:.2f} | {law:.2f} | {r['runout'] / law:.2f} |"
              if law else f"| {r['a']:g} | {r['runout']:.2f} | – | – |",
              f"{r['height']:.2f} | {r['ke_ratio']:.1e} | {r['duration']:.2f} |")

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4))
    a = [r["a"] for r in rows]
    ax.plot(a, [r["runout"] for r in rows], "o", label=f"talus MPM ({args.shape}, h = L_i/8)")
    lo = [x / 20 for x in range(1, 37)]
    hi = [2.8 + x / 10 for x in range(0, 50)]
    ax.plot(lo, [1.2 * x for x in lo], "k-", label="Lube et al. 1.2 a")
    ax.plot(hi, [1.9 * x ** (2 / 3) for x in hi], "k--", label="Lube et al. 1.9 a^(2/3)")
    ax.set_xlabel("aspect ratio a = H/L_i")
    ax.set_ylabel("run-out (L∞ − L_i)/L_i")
    ax.legend()
    ax.grid(alpha=0.3)
    bx.plot(a, [r["height"] for r in rows], "o", label="talus MPM")
    bx.plot([0, 1.15], [0, 1.15], "k-", label="Lube: H∞ = H (a < 1.15)")
    bx.set_xlabel("aspect ratio a = H/L_i")
    bx.set_ylabel("final height H∞/L_i")
    bx.legend()
    bx.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)
    print(args.png)


if __name__ == "__main__":
    main()
