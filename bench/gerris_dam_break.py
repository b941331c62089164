#!/usr/bin/python3
"""Stoker wet dam break: talus two-phase (solid fraction 0) against Gerris.

Both codes run the same flat, frictionless 100 m channel (128 cells of
0.78125 m along x, NY across, walls all round; h = 1 m for x < 50 m and
h = 0.5 m beyond, at rest; g = 9.81; t = 6 s) and are scored against the
exact solution on the centre row. Needs gerris2D (`apt-get install gerris`).

Usage: /usr/bin/python3 bench/gerris_dam_break.py [--ny 4] [--repeat 3]
"""
import argparse
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

LENGTH, NX, DAM, H_L, H_R, G, T_END = 100.0, 128, 50.0, 1.0, 0.5, 9.81, 6.0
DX = LENGTH / NX
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def stoker_middle():
    """Middle depth h_m, speed u_m and shock speed s (bisection on h_m)."""
    c_l = math.sqrt(G * H_L)

    def mismatch(h):  # rarefaction's u_m minus the shock's u_m
        u_rare = 2.0 * (c_l - math.sqrt(G * h))
        u_shock = (h - H_R) * math.sqrt(G * (h + H_R) / (2.0 * h * H_R))
        return u_rare - u_shock

    lo, hi = H_R, H_L
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if mismatch(mid) > 0.0 else (lo, mid)
    h_m = 0.5 * (lo + hi)
    u_m = 2.0 * (c_l - math.sqrt(G * h_m))
    return h_m, u_m, h_m * u_m / (h_m - H_R)


def stoker_depth(x, t):
    h_m, u_m, s = stoker_middle()
    c_l, c_m = math.sqrt(G * H_L), math.sqrt(G * h_m)
    xi = (x - DAM) / t
    fan = (2.0 * c_l - xi) ** 2 / (9.0 * G)
    return np.select([xi <= -c_l, xi <= u_m - c_m, xi <= s],
                     [H_L, fan, h_m], H_R)


def write_asc(path, grid):
    ny, nx = grid.shape
    with open(path, "w") as f:
        f.write(f"ncols {nx}\nnrows {ny}\nxllcorner 0\nyllcorner 0\n"
                f"cellsize {DX}\nNODATA_value -9999\n")
        for row in grid:  # north to south; the release is the same on all
            f.write(" ".join(f"{v:.17g}" for v in row) + "\n")


def run_talus(work, ny, binary):
    x = (np.arange(NX) + 0.5) * DX
    write_asc(os.path.join(work, "terrain.asc"), np.zeros((ny, NX)))
    write_asc(os.path.join(work, "release.asc"),
              np.tile(np.where(x < DAM, H_L, H_R), (ny, 1)))
    # Manning 0 and a negligible laminar viscosity (it must be > 0) make
    # the fluid phase plain Saint-Venant; no solid, so no drag.
    toml = f"""method = "runout"
name = "stoker"
[run]
model = "two_phase"
duration = {T_END}
stop_at_rest = false
[terrain]
file = "terrain.asc"
boundary = "wall"
order = 2
[solid]
density = 2650
internal_friction = 35
basal_friction = 20
grain_diameter = 0.001
[fluid]
density = 1000
manning = 0.0
viscosity_alpha = 1e-9
[release]
type = "raster"
file = "release.asc"
solid_fraction = 0.0
[output]
series_interval = {T_END}
"""
    scenario = os.path.join(work, "scenario.toml")
    with open(scenario, "w") as f:
        f.write(toml)
    out = os.path.join(work, "talus_out")
    t0 = time.perf_counter()
    # The end-of-run "still moving" warning is expected: a dam break never
    # comes to rest in 6 s.
    subprocess.run([binary, "run", scenario, "--out", out, "--force",
                    "-j", "1", "--quiet"], check=True,
                   stderr=subprocess.DEVNULL)
    process = time.perf_counter() - t0
    with open(os.path.join(out, "summary.json")) as f:
        run = json.load(f)["run"]
    depth = np.load(os.path.join(out, "deposit.npy"))[::-1]  # row 0 south
    return depth, run["steps"], run["loop_wall_s"], process


def run_gerris(work, ny):
    # Gerris boxes are square: NX/ny boxes of ny x ny cells (level log2 ny)
    # give the same regular grid as talus. Box 1 is centred on the origin,
    # so Gerris x, y = ours - box/2.
    level = int(math.log2(ny))
    nbox, box = NX // ny, ny * DX
    walls = "top = Boundary { BcDirichlet V 0 } " \
            "bottom = Boundary { BcDirichlet V 0 }"
    lines = [f"{nbox} {nbox - 1} GfsRiver GfsBox GfsGEdge {{}} {{",
             f"  PhysicalParams {{ L = {box} g = {G} }}",
             f"  Refine {level}",
             f"  Init {{}} {{ P = (x + {box / 2} < {DAM} ? {H_L} : {H_R}) }}",
             f"  Time {{ end = {T_END} }}",
             "  OutputTime { start = end } stderr",
             "  OutputSimulation { start = end } depth.txt "
             "{ format = text variables = P }",
             "}"]
    # Without explicit walls an earlier try gave wrong results.
    for i in range(nbox):
        b = walls
        if i == 0:
            b += " left = Boundary { BcDirichlet U 0 }"
        if i == nbox - 1:
            b += " right = Boundary { BcDirichlet U 0 }"
        lines.append(f"GfsBox {{ {b} }}")
    lines += [f"{i} {i + 1} right" for i in range(1, nbox)]
    with open(os.path.join(work, "stoker.gfs"), "w") as f:
        f.write("\n".join(lines) + "\n")
    t0 = time.perf_counter()
    log = subprocess.run(["gerris2D", "stoker.gfs"], cwd=work, check=True,
                         capture_output=True, text=True).stderr
    process = time.perf_counter() - t0
    # "step: N t: T dt: D cpu: C real: R" at the end; real = loop wall time.
    m = re.findall(r"step:\s*(\d+)\s+t:\s*(\S+).*real:\s*(\S+)", log)
    if not m or abs(float(m[-1][1]) - T_END) > 1e-9:
        sys.exit(f"gerris_dam_break: unexpected Gerris log:\n{log}")
    steps, loop = int(m[-1][0]), float(m[-1][2])
    cells = np.loadtxt(os.path.join(work, "depth.txt"), comments="#")
    depth = np.full((ny, NX), np.nan)
    i = np.floor((cells[:, 0] + box / 2) / DX).astype(int)
    j = np.floor((cells[:, 1] + box / 2) / DX).astype(int)
    depth[j, i] = cells[:, 3]
    if np.isnan(depth).any():
        sys.exit("gerris_dam_break: Gerris output does not cover the grid")
    return depth, steps, loop, process


def score(depth):
    """Plateau error, shock position and height on the centre row."""
    h = depth[depth.shape[0] // 2]
    x = (np.arange(NX) + 0.5) * DX
    h_m, u_m, s = stoker_middle()
    tail = DAM + (u_m - math.sqrt(G * h_m)) * T_END
    front = DAM + s * T_END
    # Plateau level, two cells clear of the tail and the shock so that it
    # measures the middle state, not the smearing of the waves.
    on = (x > tail + 2 * DX) & (x < front - 2 * DX)
    plateau = np.mean(np.abs(h[on] - h_m))
    # Shock: the last crossing of the mid depth, interpolated.
    half = 0.5 * (h_m + H_R)
    k = np.nonzero((h[:-1] >= half) & (h[1:] < half))[0][-1]
    x_s = x[k] + (h[k] - half) / (h[k] - h[k + 1]) * DX
    behind = np.mean(h[(x > x_s - 6 * DX) & (x < x_s - 2 * DX)])
    ahead = np.mean(h[(x > x_s + 2 * DX) & (x < x_s + 6 * DX)])
    profile = np.sum(np.abs(h - stoker_depth(x, T_END))) * DX
    spread = np.max(np.ptp(depth, axis=0))
    jump = (behind - ahead) - (h_m - H_R)
    return plateau, x_s - front, jump, profile, spread


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ny", type=int, default=4,
                    choices=[2, 4, 8, 16, 32, 64, 128],
                    help="cells across the channel (default 4)")
    ap.add_argument("--repeat", type=int, default=3,
                    help="runs per code; the median time is reported")
    ap.add_argument("--talus", default=os.path.join(ROOT, "build", "talus"))
    a = ap.parse_args()
    if shutil.which("gerris2D") is None:
        sys.exit("gerris_dam_break: gerris2D not found; "
                 "install it with `apt-get install gerris`")
    if not os.access(a.talus, os.X_OK):
        sys.exit(f"gerris_dam_break: no talus binary at {a.talus}")

    h_m, u_m, s = stoker_middle()
    tail = DAM + (u_m - math.sqrt(G * h_m)) * T_END
    head = DAM - math.sqrt(G * H_L) * T_END
    front = DAM + s * T_END
    assert 0.0 < head and front < LENGTH, "waves leave the domain"
    print(f"Stoker: h_l {H_L} m, h_r {H_R} m, t {T_END} s: h_m {h_m:.6f} m, "
          f"u_m {u_m:.6f} m/s, fan {head:.3f}-{tail:.3f} m, "
          f"shock at {front:.3f} m (s {s:.4f} m/s)")
    print(f"grid {NX} x {a.ny} cells of {DX} m, walls; centre row "
          f"{a.ny // 2} (from the south); median of {a.repeat} runs\n")

    codes = {"talus": lambda w: run_talus(w, a.ny, a.talus),
             "Gerris": lambda w: run_gerris(w, a.ny)}
    runs = {name: [] for name in codes}
    # Alternate the codes so that a shared machine's drift hits both alike.
    for _ in range(a.repeat):
        for name, run in codes.items():
            with tempfile.TemporaryDirectory(prefix="stoker_") as work:
                runs[name].append(run(work))
    rows = []
    for name, rs in runs.items():
        depth, steps = rs[-1][0], rs[-1][1]
        loop = statistics.median(r[2] for r in rs)
        process = statistics.median(r[3] for r in rs)
        rows.append((name, steps, loop, process, NX * a.ny * steps / loop)
                    + score(depth))

    print("| code | steps | loop wall (s) | process wall (s) | "
          "cell-updates/s (loop) | plateau mean abs err (m) | "
          "shock x err (m) | shock height err (m) | profile L1 (m^2) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, steps, loop, proc, rate, plat, dxs, dhs, prof, _ in rows:
        print(f"| {name} | {steps} | {loop:.4f} | {proc:.3f} | {rate:.3g} | "
              f"{plat:.2e} | {dxs:+.3f} | {dhs:+.2e} | {prof:.4f} |")
    for name, *_, spread in rows:
        print(f"{name}: largest depth difference across rows {spread:.1e} m")


if __name__ == "__main__":
    main()
