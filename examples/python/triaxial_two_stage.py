"""A two-stage triaxial-like test scripted in Python: a cubical cell of six
frictionless plane walls around a random packing of spheres; stage 1
consolidates it isotropically (a servo on every wall holds the pressure p0),
stage 2 shears it (the top wall moves down at a constant speed, the bottom
one stays, the four side walls keep p0: the cell's conventional triaxial
compression). The script changes the walls' motion between the stages and
keeps each servo's area equal to the face it presses on as the sample
deforms.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/triaxial_two_stage.py \
        --out runs/triaxial_py [--strain 0.1] [--pressure 2e4]

Writes OUT/run/ (the run folder: summary.json, series.csv, log.txt),
OUT/triaxial.csv (per sample: time, stage, the cell's sides, the stresses on
the walls, axial and volumetric strain, the mobilised friction
sin(phi) = (s1 - s3)/(s1 + s3)) and OUT/triaxial.png.
"""
import argparse
import math
import os

import numpy as np

import talus

SIDE = 0.03         # m, the cube the grains are poured into
# Each wall: the axis it faces along and the sign of its inward normal.
WALLS = {"bottom": (2, 1.0), "top": (2, -1.0), "left": (0, 1.0), "right": (0, -1.0),
         "front": (1, 1.0), "back": (1, -1.0)}


def scenario(duration, r_min, r_max, friction_angle):
    """The sample as a dict: spheres, no gravity, six planes whose normals
    point into the cell; the servos are set from Python."""
    walls = []
    for name, (axis, sign) in WALLS.items():
        point, normal = [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]
        point[axis] = 0.0 if sign > 0 else SIDE
        normal[axis] = sign
        walls.append({"name": name, "type": "plane", "material": "plate", "point": point,
                      "normal": normal})
    return {
        "method": "dem", "name": "triaxial_py",
        "description": "two-stage triaxial-like test of a cubical cell (Python)",
        "run": {"dimension": 3, "duration": duration, "gravity": [0.0, 0.0, 0.0],
                "domain": {"min": [-0.01] * 3, "max": [SIDE + 0.01] * 3}},
        "contact": {"model": "linear"},
        "materials": [
            {"name": "grain", "density": 2650, "friction_angle": friction_angle,
             "normal_stiffness": 1e5, "damping_ratio": 0.3},
            {"name": "plate", "friction_angle": 0.0, "normal_stiffness": 1e5,
             "damping_ratio": 0.3}],
        "walls": walls,
        "particles": [{"type": "random_fill", "material": "grain",
                       "box": {"min": [0.0] * 3, "max": [SIDE] * 3},
                       "radius_min": r_min, "radius_max": r_max, "porosity": 0.45,
                       "shrink": 0.03}],
        "output": {"series_interval": 0.005, "snapshots": False},
    }


def cell(walls):
    """The cell's three sides now (x, y, z), from the walls' displacements."""
    return np.array([SIDE + walls[b].displacement[a] - walls[f].displacement[a]
                     for a, f, b in ((0, "left", "right"), (1, "front", "back"),
                                     (2, "bottom", "top"))])


def face_area(name, sides):
    axis = WALLS[name][0]
    return float(np.prod(np.delete(sides, axis)))


def stresses(walls, sides):
    """Mean normal stress on each pair of faces (x, y, z), Pa, compression
    positive: the walls' forces over the faces' areas."""
    out = []
    for axis, pair in enumerate((("left", "right"), ("front", "back"), ("bottom", "top"))):
        force = 0.5 * sum(abs(walls[n].force[axis]) for n in pair)
        out.append(force / face_area(pair[0], sides))
    return np.array(out)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--pressure", type=float, default=2e4, help="p0, Pa")
    ap.add_argument("--strain", type=float, default=0.1, help="axial strain to shear to")
    ap.add_argument("--consolidation", type=float, default=0.1, help="stage 1, s")
    ap.add_argument("--shear-speed", type=float, default=0.01, help="top wall, m/s")
    ap.add_argument("--radius", type=float, nargs=2, default=[1.6e-3, 2.4e-3])
    ap.add_argument("--friction-angle", type=float, default=26.57, help="grains, deg")
    ap.add_argument("--servo-speed", type=float, default=0.1,
                    help="the servos' largest speed, m/s: their gain (see below)")
    ap.add_argument("--threads", type=int, default=1)
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    p0 = args.pressure
    shear_time = 1.5 * args.strain * SIDE / args.shear_speed  # ample: the script ends it
    sc = talus.load_scenario(scenario(args.consolidation + shear_time, *args.radius,
                                      args.friction_angle))
    rows = []

    def record(run, stage):
        """One row of the table; the walls and the cell's sides now."""
        walls = run.walls()
        sides = cell(walls)
        rows.append([run.time, stage, *sides, *stresses(walls, sides),
                     walls["top"].displacement[2]])
        return walls, sides

    def hold(walls, sides, names):
        """Each servo holds p0 over the face it presses on now."""
        for name in names:
            walls[name].set_servo(p0, args.servo_speed, face_area(name, sides))

    sides_of = ["left", "right", "front", "back"]
    with talus.Run(sc, out=os.path.join(args.out, "run"), force=True,
                   threads=args.threads) as run:
        # Stage 1: every wall holds p0.
        hold(run.walls(), np.full(3, SIDE), list(WALLS))

        def consolidate(run):
            hold(*record(run, 1), list(WALLS))

        run.run(until=args.consolidation, every_time=0.002, callback=consolidate)
        walls, sides0 = record(run, 1)
        consolidated = {name: w.pressure for name, w in walls.items()}
        # Stage 2: the top and bottom servos off, the top moves down, the sides keep p0.
        walls["bottom"].set_servo(0.0)
        walls["top"].set_servo(0.0)
        walls["top"].set_velocity([0.0, 0.0, -args.shear_speed])
        t_shear, top_shear = run.time, walls["top"].displacement[2]

        def shear(run):
            walls, sides = record(run, 2)
            hold(walls, sides, sides_of)
            return math.log(sides0[2] / sides[2]) >= args.strain  # True ends the run

        run.run(every_time=0.002, callback=shear)
        if rows[-1][0] != run.time:  # ended by the scenario's duration, not the callback
            record(run, 2)
        t_end, top_end = run.time, rows[-1][-1]

    keys = ["time", "stage", "side_x", "side_y", "side_z", "s_xx", "s_yy", "s_zz", "top_z"]
    table = np.array(rows)
    col = {k: i for i, k in enumerate(keys)}
    stage2 = table[:, col["stage"]] == 2
    sides = table[:, col["side_x"]:col["side_z"] + 1]
    eps_axial = np.where(stage2, np.log(sides0[2] / sides[:, 2]), 0.0)
    eps_vol = np.where(stage2, np.log(np.prod(sides0) / np.prod(sides, axis=1)), 0.0)
    s1 = table[:, col["s_zz"]]
    s3 = 0.5 * (table[:, col["s_xx"]] + table[:, col["s_yy"]])
    sin_phi = (s1 - s3) / (s1 + s3)
    with open(os.path.join(args.out, "triaxial.csv"), "w") as f:
        f.write(",".join(keys + ["eps_axial", "eps_vol", "sin_phi"]) + "\n")
        for k, r in enumerate(table):
            f.write(",".join(f"{v:.9g}" for v in r) +
                    f",{eps_axial[k]:.9g},{eps_vol[k]:.9g},{sin_phi[k]:.9g}\n")
    result = {
        "consolidated_pressures": consolidated,
        "sides_consolidated": sides0.tolist(),
        "shear_start": t_shear,
        "top_speed_in_shear": -(top_end - top_shear) / (t_end - t_shear),
        "axial_strain": float(eps_axial[-1]),
        "lateral_stress_in_shear": (float(s3[stage2].min()), float(s3[stage2].max())),
        "peak_sin_phi": float(sin_phi[stage2].max()),
        "final_sin_phi": float(sin_phi[-1]),
        "volumetric_strain_end": float(eps_vol[-1]),
        "folder": run.out,
    }
    print("consolidated: wall pressures " +
          ", ".join(f"{k} {v:.6g}" for k, v in consolidated.items()) +
          f" Pa (p0 = {p0:g}); sheared to axial strain {result['axial_strain']:.3f}: peak "
          f"sin(phi) {result['peak_sin_phi']:.3f}, at the end {result['final_sin_phi']:.3f}; "
          f"volumetric strain {result['volumetric_strain_end']:.4f} (compression positive); lateral "
          f"stress in shear {result['lateral_stress_in_shear'][0]:.6g}.."
          f"{result['lateral_stress_in_shear'][1]:.6g} Pa")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return result
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.5))
    a.plot(eps_axial[stage2], sin_phi[stage2])
    a.set_xlabel("axial strain")
    a.set_ylabel("sin(phi) = (s1 - s3) / (s1 + s3)")
    b.plot(eps_axial[stage2], eps_vol[stage2])
    b.set_xlabel("axial strain")
    b.set_ylabel("volumetric strain (compression +)")
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "triaxial.png"), dpi=100)
    return result


if __name__ == "__main__":
    main()
