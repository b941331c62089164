#!/usr/bin/python3
"""plots/plot.py, the one plotting entry point, on short runs of bundled scenarios by
name: the DAN flume, fv2d on terrain and on the flume's path, the two-phase debris
flow, a DEM column collapse, an MPM column collapse and the plan-view clay block. For
each, plot.py picks the scripts from summary.json, exits 0 and prints only PNG paths,
each a real PNG in RUN_DIR/plots, with the ones its method's script draws among them.
A folder without summary.json is refused (exit 2).

Args: <talus binary> <source dir>. Run with Debian's /usr/bin/python3.
"""
import os
import subprocess
import sys
import tempfile

from checks import Checks

talus, src = sys.argv[1], sys.argv[2]
check = Checks()
PNG = b"\x89PNG\r\n\x1a\n"

# name, --set values that keep the run short, PNG names the fitting scripts write.
RUNS = [
    ("runout_flume_A", [], {"front.png", "deposit.png"}),
    ("runout_terrain_2d", ["run.duration=10"], {"max_height.png", "deposit.png"}),
    ("runout_flume_A_fv2d", ["run.duration=1"], {"front.png", "deposit.png"}),
    ("two_phase_debris_valley", ["run.duration=5"], {"max_height.png", "solid_fraction.png"}),
    ("column_collapse", ["run.duration=0.002", "output.snapshot_interval=0.001",
                         "particles.0.box={min=[0,0,0],max=[0.01206,0.00804,0.02412]}"],
     {"energy.png", "contacts.png"}),
    ("mpm_column_collapse", ["run.duration=0.01"], {"front.png"}),
    # Cohesion loss (critical_volume_strain): the clay block's crack map as well.
    ("mpm_clay_block_plan", ["run.duration=0.01"], {"front.png", "cracks.png"}),
]

with tempfile.TemporaryDirectory() as tmp:
    for name, sets, expected in RUNS:
        out = os.path.join(tmp, name)
        cmd = [talus, "run", name, "--out", out, "-q", "--threads", "1"]
        for s in sets:
            cmd += ["--set", s]
        r = subprocess.run(cmd, capture_output=True, text=True)
        check(f"{name}: the run ends (exit 0)", r.returncode == 0)
        if r.returncode != 0:
            print(r.stderr)
            continue
        p = subprocess.run(["/usr/bin/python3", os.path.join(src, "plots", "plot.py"), out],
                           capture_output=True, text=True)
        check(f"{name}: plot.py exits 0", p.returncode == 0)
        if p.returncode != 0:
            print(p.stdout, p.stderr)
        lines = p.stdout.split()
        check(f"{name}: plot.py prints only PNG paths", lines and
              all(line.endswith(".png") for line in lines))
        for png in lines:
            check(f"{png} lies in the run's plots/",
                  os.path.dirname(os.path.abspath(png)) == os.path.join(out, "plots"))
            with open(png, "rb") as f:
                check(f"{png} is a PNG", f.read(8) == PNG)
        names = {os.path.basename(line) for line in lines}
        check(f"{name}: {sorted(expected)} among {sorted(names)}", expected <= names)

    empty = os.path.join(tmp, "empty")
    os.makedirs(empty)
    p = subprocess.run(["/usr/bin/python3", os.path.join(src, "plots", "plot.py"), empty],
                       capture_output=True, text=True)
    check("a folder without summary.json is refused (exit 2)",
          p.returncode == 2 and "summary.json" in p.stderr)

check.finish("plot entry")
