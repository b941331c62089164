#!/usr/bin/python3
"""Vibration convection (Götz 2024 ch. 6) over several variants of one scenario: run, coarse-grain,
plot, and tabulate the convection strength.

Feeds docs/validation/convection.md, section "Wall friction 0 / 0.25 / 0.5 / 0.75 over
Götz's 15 periods".

Usage: convection_sweep.py TALUS SCENARIO OUT_DIR LABEL=SET[;SET...] [LABEL=...]
                           [--threads N] [--period P] [--from T0] [--cells NX,NY,NZ] [--vmax V]
Example (Götz's Fig. 44, wall friction 0 / 0.25 / 0.5 / 0.75):
  convection_sweep.py build/talus scenarios/dem/vibration_convection.toml runs/conv \
      mu0=contact.pairs.0.friction=0 mu025=contact.pairs.0.friction=0.25 \
      mu05=contact.pairs.0.friction=0.5 mu075=contact.pairs.0.friction=0.75

A run folder that already holds a summary.json is not run again (the sweep can be resumed).
Per variant: `talus analyse coarse-grain` (snapshots one period apart, the first period left out
with --from), plots/plot_coarse_grain.py with one arrow scale for all, and a table row.

Strength measures, all in units of f d_mean (Götz's unit):
- rz_mean: mean |v| of the azimuthal r-z average, weighted by solid fraction x ring volume.
  Averaging over the azimuth cancels most of the random motion of single grains, so this is
  the ordered (convective) flow; the same quantity of a field without convection is its
  noise floor (the frictionless case shows it).
- field_mean: coarse_grain.json's mass-weighted mean |v| over all cells (noise included).
- axis lower / upper / whole: mean v_z of the 3 mm column around the axis (Götz §6.3.2).
- side cell x (y): half the difference of the mean v_z of the outer columns at -x and +x (-y, +y),
  as plot_coarse_grain.py prints them: one cell that rises on one side and sinks on the other
  (the tilted container of Götz §6.4) makes the x value large; the symmetric flow leaves both small.
"""
import argparse
import json
import math
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "plots"))
from plot_coarse_grain import side_vz  # noqa: E402
from talus_csv import read_columns  # noqa: E402


def rz_strength(cg_dir, scale):
    rz = read_columns(os.path.join(cg_dir, "rz.csv"))
    rs = sorted(set(rz["r"]))
    dr = rs[1] - rs[0] if len(rs) > 1 else 1.0
    num = den = 0.0
    for r, phi, vr, vz in zip(rz["r"], rz["solid_fraction"], rz["v_r"], rz["v_z"]):
        w = phi * 2 * math.pi * r * dr  # ring volume per unit height x solid fraction
        num += w * math.hypot(vr, vz)
        den += w
    return scale * num / den if den > 0 else float("nan")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("talus")
    ap.add_argument("scenario")
    ap.add_argument("out")
    ap.add_argument("variants", nargs="+", help="LABEL=key=value[;key=value...] (LABEL= for none)")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--period", type=float, default=1 / 12)
    ap.add_argument("--from", dest="t0", type=float, default=0.08)
    ap.add_argument("--cells", default="9,9,22")
    ap.add_argument("--vmax", default="2.2")
    a = ap.parse_args()
    rows = []
    for spec in a.variants:
        label, _, sets = spec.partition("=")
        out = os.path.join(a.out, label)
        if not os.path.exists(os.path.join(out, "summary.json")):
            cmd = [a.talus, "run", a.scenario, "--out", out, "--force", "--quiet",
                   "--threads", str(a.threads)]
            for s in filter(None, sets.split(";")):
                cmd += ["--set", s]
            print(" ".join(cmd), flush=True)
            subprocess.run(cmd, check=True)
        subprocess.run([a.talus, "analyse", "coarse-grain", out, "--cells", a.cells,
                        "--period", f"{a.period:.13g}", "--from", f"{a.t0:g}"], check=True,
                       stdout=subprocess.DEVNULL)
        cg = os.path.join(out, "coarse_grain")
        subprocess.run([sys.executable, os.path.join(HERE, "..", "plots", "plot_coarse_grain.py"),
                        cg, f"{label} ({sets or 'as the file'})", a.vmax], check=True,
                       stdout=subprocess.DEVNULL)
        meta = json.load(open(os.path.join(cg, "coarse_grain.json")))
        field = {k: np.array(v) for k, v in read_columns(os.path.join(cg, "field.csv")).items()}
        side = side_vz(meta, field)
        wall = json.load(open(os.path.join(out, "summary.json"))).get("run", {})
        rows.append([label, str(meta["intervals"]),
                     f"{rz_strength(cg, meta['period'] / meta['mean_diameter']):.3f}",
                     f"{meta['mean_speed_normalised']:.3f}",
                     f"{meta['axis_lower_vz_normalised']:+.3f}", f"{meta['axis_upper_vz_normalised']:+.3f}",
                     f"{meta['axis_vz_normalised']:+.3f}", f"{0.5 * (side['-x'] - side['+x']):+.3f}",
                     f"{0.5 * (side['-y'] - side['+y']):+.3f}", f"{wall.get('loop_wall_s', float('nan')):.0f}"])
    print("| variant | periods averaged | rz_mean | field_mean | axis lower | axis upper | axis whole "
          "| side cell x | side cell y | loop wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print("| " + " | ".join(r) + " |")


if __name__ == "__main__":
    main()
