"""What both clay-block run tests (test_clay_block_run.py in 3D, test_clay_block_plan_run.py in
plan view) read from a finished run and check alike. Not a test itself (not test_*.py)."""
import csv
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "plots"))
from plot_mpm import read_points, snapshots  # noqa: E402


def crack_metrics(out, band=None):
    """Runs plots/plot_clay_block.py on the run folder and returns its cracks.json."""
    cmd = ["/usr/bin/python3", os.path.join(ROOT, "plots", "plot_clay_block.py"), out]
    if band is not None:
        cmd += ["--band", str(band)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "cracks.json")) as f:
        return json.load(f)


def check_yield_and_rest(check, name, out):
    """Every point that lost cohesion has yielded (mpm.md: cohesion is lost only on the yield
    surface) and the block is at rest at the end (kinetic energy below 1 % of the start's).
    Returns the mask of the points that lost cohesion."""
    _, d = read_points(snapshots(out)[-1][1], ("c_over_c0", "plastic_strain"))
    lost = d["c_over_c0"] < 1.0
    check(f"{name}: every point that lost cohesion has yielded",
          bool((d["plastic_strain"][lost] > 0.0).all()))
    with open(os.path.join(out, "series.csv")) as f:
        rows = list(csv.DictReader(f))
    ke0, ke1 = float(rows[0]["kinetic_energy"]), float(rows[-1]["kinetic_energy"])
    print(f"{name}: kinetic energy {ke0:.3g} J -> {ke1:.3g} J")
    check(f"{name}: at rest at the end (KE < 1 % of the start)", ke1 < 0.01 * ke0)
    return lost
