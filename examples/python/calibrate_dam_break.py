"""Two-parameter calibration of the DEM dam break with scipy.optimize: the
grain friction angle and Kuen's rolling factor fitted to the lab slope angles
(Kuen 2011, Table 7), where `talus calibrate` sweeps one parameter on a grid.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/calibrate_dam_break.py \
        --out runs/calibration [--evaluations 20]

Each evaluation is one run (OUT/run_NN); OUT/calibration.json lists every
evaluation (parameters, measured angles, misfit) and the best. The default
grains are twice the scenario's (2-4 mm, about 15 s a run on one core), so
that the example finishes in minutes; --fine uses the scenario's own 1-2 mm
grains (about four times longer).
"""
import argparse
import json
import math
import os

import numpy as np
from scipy.optimize import minimize

import talus

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SCENARIO = os.path.join(ROOT, "scenarios", "dem", "dam_break.toml")
# The lab's slope angles in 0.1 m segments from the toe (deg; the scenario's comment).
LAB = {"gamma_3": 21.562, "gamma_4": 28.740, "gamma_5": 30.644}
# (key, lower, upper): the grain friction angle (deg) and Kuen's rolling factor.
PARAMETERS = [("materials.0.friction_angle", 5.0, 40.0),
              ("contact.kuen_particle_factor", 0.1, 1.0)]
COARSE = {"dam_break.release.radius_min": 2e-3, "dam_break.release.radius_max": 4e-3,
          "output.snapshots": False}
# A segment the deposit does not reach has no angle: it counts as 90 deg off.
MISSING = 90.0


def number(text):
    """A --set value: an integer where it reads as one, else a float."""
    try:
        return int(text)
    except ValueError:
        return float(text)


def misfit(summary, targets):
    """Sum of squared differences of the measured angles from the targets (deg^2)."""
    angles = summary["dam_break"]
    return sum((angles[k] - v) ** 2 if angles.get(k) is not None else MISSING ** 2
               for k, v in targets.items())


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--evaluations", type=int, default=20)
    ap.add_argument("--fine", action="store_true", help="the scenario's own grains (slow)")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="more overrides, as talus run --set (numbers only)")
    ap.add_argument("--target", action="append", default=[], metavar="GAMMA=DEG",
                    help="targets instead of the lab's (e.g. gamma_1=20)")
    ap.add_argument("--threads", type=int, default=1)
    args = ap.parse_args(argv)
    targets = dict((k, float(v)) for k, v in (t.split("=") for t in args.target)) or LAB
    fixed = {} if args.fine else dict(COARSE)
    fixed.update((k, number(v)) for k, v in (s.split("=") for s in args.set))
    os.makedirs(args.out, exist_ok=True)
    evaluations = []

    def objective(x):
        overrides = dict(fixed, **{key: float(v) for (key, _, _), v in zip(PARAMETERS, x)})
        folder = os.path.join(args.out, f"run_{len(evaluations):02d}")
        data = talus.run(SCENARIO, out=folder, overrides=overrides, force=True,
                         threads=args.threads)
        value = misfit(data.summary, targets)
        evaluations.append({"folder": folder, "parameters": [float(v) for v in x],
                            "angles": {k: data.summary["dam_break"].get(k) for k in targets},
                            "misfit": value})
        print(f"{len(evaluations):3d}  " + "  ".join(f"{v:8.4f}" for v in x) +
              f"  misfit {value:9.3f} deg^2", flush=True)
        return value

    # A wide first simplex around the scenario's friction angle and a mid rolling
    # factor: the angles of a few hundred disks scatter by degrees from run to
    # run, so small first moves would only measure that scatter.
    simplex = np.array([[15.5, 0.5], [25.0, 0.5], [15.5, 0.9]])
    result = minimize(objective, simplex[0], method="Nelder-Mead",
                      bounds=[(lo, hi) for _, lo, hi in PARAMETERS],
                      options={"maxfev": args.evaluations, "xatol": 0.2, "fatol": 0.05,
                               "initial_simplex": simplex})
    best = min(range(len(evaluations)), key=lambda k: evaluations[k]["misfit"])
    report = {"parameters": [key for key, _, _ in PARAMETERS], "targets": targets,
              "fixed": fixed, "evaluations": evaluations, "best": best,
              "converged": bool(result.success), "optimizer_message": str(result.message)}
    with open(os.path.join(args.out, "calibration.json"), "w") as f:
        json.dump(report, f, indent=1)
    e = evaluations[best]
    print(f"best (run_{best:02d}): " +
          ", ".join(f"{k} = {v:.4g}" for k, v in zip(report["parameters"], e["parameters"])) +
          f"; misfit {e['misfit']:.3f} deg^2, rms {math.sqrt(e['misfit'] / len(targets)):.2f} deg")
    return report


if __name__ == "__main__":
    main()
