#!/usr/bin/python3
"""The clay blocks of van den Bout §3 (scenarios/mpm/mpm_clay_block*.toml) on a coarse grid
(4 cm cells instead of 2 cm; about 2000 points each), run by the real binary and read by
plots/plot_clay_block.py.

What is asserted, and why:
- the crack indicator is physical: every point with c/c0 < 1 has yielded (plastic strain
  > 0), since cohesion is lost only on the yield surface (mpm.md "Cohesion loss");
- the weaker clay (18.3 kPa, 27 deg) loses more of its bonds than the stronger (26.7 kPa,
  28 deg) in the same impact: its fraction of damaged points (c/c0 < 0.5) is larger.
  (The direction is the source's; on this grid it was seen before this test was written:
  0.48 against 0.36 on the first geometry, 0.47 against 0.38 on the second, whose block
  started inside the obstacle; 0.344 against 0.252 on the corrected start;
  docs/validation.md "Clay block".)
- both blocks come to rest against the obstacle and the run-out: the kinetic energy at the
  end is below 1 % of the start's (72 J at 2 m/s).
The source's finer claim (a crack from the obstacle corner over half the weak block's length,
only local damage in the strong one) is not asserted on this 3D set-up: the one 3D set-up that
showed it (scenarios/mpm/mpm_clay_block_runout*.toml) shows it on 2.5 cm cells at 0.30-0.45 m/s
only, not on 2 or 4 cm cells (docs/validation.md "Clay block"). It is asserted in plan view,
with a non-local cohesion loss, by test_clay_block_plan_run.py.

Args: <talus binary> <source dir>. Run with Debian's /usr/bin/python3 (python3-vtk9).
"""
import json
import os
import subprocess
import sys
import tempfile

from checks import Checks
from clay_block_checks import check_yield_and_rest, crack_metrics

talus, src = sys.argv[1], sys.argv[2]
check = Checks()


def run(tmp, name):
    out = os.path.join(tmp, name)
    subprocess.run([talus, "run", os.path.join(src, "scenarios", "mpm", name + ".toml"), "--out", out,
                    "--quiet", "--threads", "1", "--set", "grid.cell_size=0.04",
                    "--set", "output.snapshot_interval=0.3"], check=True)
    return out


with tempfile.TemporaryDirectory() as tmp:
    damaged = {}
    for name in ("mpm_clay_block", "mpm_clay_block_strong"):
        out = run(tmp, name)
        cracks = crack_metrics(out)
        damaged[name] = cracks["damaged_fraction"]
        print(name, json.dumps(cracks))
        lost = check_yield_and_rest(check, name, out)
        check(f"{name}: some cohesion is lost", lost.any())
        check(f"{name}: a png of the cracks", os.path.getsize(os.path.join(out, "plots",
                                                                           "cracks.png")) > 0)
    check("the weak clay is more damaged than the strong",
          damaged["mpm_clay_block"] > damaged["mpm_clay_block_strong"])

check.finish("clay block run")
