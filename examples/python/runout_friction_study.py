"""A parameter study from Python: the bundled 2D runout (fv2d, Voellmy) for a
range of basal friction coefficients, the run-out read from the depth array
of each finished run, a table and a plot.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/runout_friction_study.py \
        --out runs/friction_study [--mu 0.1 0.15 0.2 0.3 0.4]

Writes OUT/mu_<value>/ (one run each), OUT/study.csv and OUT/study.png.
"""
import argparse
import os

import numpy as np

import talus

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SCENARIO = os.path.join(ROOT, "scenarios", "runout", "runout_terrain_2d.toml")
DEPOSIT = 0.01  # m: a cell deeper than this holds deposit


def one_run(mu, out, duration):
    overrides = {"material.friction_coefficient": mu}
    if duration is not None:
        overrides["run.duration"] = duration
    with talus.Run(SCENARIO, out=os.path.join(out, f"mu_{mu:g}"), overrides=overrides,
                   force=True) as run:
        run.run()
        h = run.arrays()["h"].copy()  # row 0 north, column 0 west (docs/python.md)
    data = talus.read_run(run.out)
    grid = data.summary["resolved"]
    dx = grid["cell_size_m"][0]
    columns = np.nonzero((h > DEPOSIT).any(axis=0))[0]
    # The terrain falls towards the east: the run-out is the easternmost
    # deposit, measured from the grid's west edge.
    runout = (columns.max() + 1) * dx if columns.size else float("nan")
    m = data.summary["metrics"]
    ended = ("at rest" if m["at_rest"] else
             "momentum below the stop fraction" if m["stopped_by_momentum"] else "still moving")
    return {"mu": mu, "runout_x_m": runout, "affected_area_m2": m["affected_area_m2"],
            "max_speed_m_s": m["max_speed_m_s"], "ended": ended,
            "time_s": data.series["time"].iloc[-1]}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--mu", type=float, nargs="+", default=[0.1, 0.15, 0.2, 0.3, 0.4])
    ap.add_argument("--duration", type=float, help="shorter than the scenario's (tests)")
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    rows = [one_run(mu, args.out, args.duration) for mu in sorted(args.mu)]
    keys = list(rows[0])
    with open(os.path.join(args.out, "study.csv"), "w") as f:
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join(str(r[k]) for k in keys) + "\n")
    for r in rows:
        print(f"mu {r['mu']:5.3f}: run-out x = {r['runout_x_m']:.1f} m, affected "
              f"{r['affected_area_m2']:.0f} m^2, max speed {r['max_speed_m_s']:.2f} m/s, "
              f"ended at {r['time_s']:.1f} s ({r['ended']})")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.5))
    mu = [r["mu"] for r in rows]
    a.plot(mu, [r["runout_x_m"] for r in rows], "o-")
    a.set_xlabel("Voellmy friction coefficient μ")
    a.set_ylabel("run-out from the west edge (m)")
    b.plot(mu, [r["max_speed_m_s"] for r in rows], "o-")
    b.set_xlabel("Voellmy friction coefficient μ")
    b.set_ylabel("peak speed (m/s)")
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "study.png"), dpi=120)
    print(os.path.join(args.out, "study.png"))
    return rows


if __name__ == "__main__":
    main()
