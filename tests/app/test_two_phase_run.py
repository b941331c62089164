#!/usr/bin/python3
"""The bundled two-phase debris flow (scenarios/runout/two_phase_debris_valley.toml,
60 s of its 120 s) end to end through the talus binary: the maps of each
phase, the series and summary.json agree with each other, the snapshots are
listed, and plots/plot_runout2d.py draws the two-phase maps as PNGs.

Args: <talus binary> <source dir>. Run with Debian's /usr/bin/python3.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

talus, src = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(src, "plots"))
from talus_csv import read_columns  # noqa: E402

from checks import Checks  # noqa: E402

check = Checks()
MAPS = ["max_height", "max_solid_height", "max_fluid_height", "max_solid_speed",
        "max_fluid_speed", "max_pressure", "max_solid_pressure", "max_fluid_pressure",
        "deposit", "deposit_solid", "deposit_fluid", "solid_fraction", "arrival_time",
        "elevation"]

with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "valley")
    subprocess.run([talus, "run", os.path.join(src, "scenarios", "runout", "two_phase_debris_valley.toml"),
                    "--out", out, "-q", "--threads", "1", "--set", "run.duration=60"], check=True)
    s = json.load(open(os.path.join(out, "summary.json")))
    m = s["metrics"]
    check("status and model", s["status"] == "completed" and s["model"] == "two_phase")
    maps = {}
    for name in MAPS:
        check(f"{name}.tif written", os.path.getsize(os.path.join(out, name + ".tif")) > 0)
        maps[name] = np.load(os.path.join(out, name + ".npy"))
        check(f"{name} on the 100 x 50 grid", maps[name].shape == (50, 100))
    dx, dy = s["resolved"]["cell_size_m"]
    # Each phase's released volume (scripts/make_debris_valley.py: 5000 m^3 at
    # a mean solid fraction of 0.55), kept to round-off with what left the grid.
    check("released solid", abs(m["released_solid_volume_m3"] - 2750.0) < 1e-9)
    check("released fluid", abs(m["released_fluid_volume_m3"] - 2250.0) < 1e-9)
    check("solid balance", m["solid_volume_error_relative"] < 1e-12)
    check("fluid balance", m["fluid_volume_error_relative"] < 1e-12)
    # The maps add up: mixture = solid + fluid, the fraction their ratio.
    check("deposit = solid + fluid", np.allclose(maps["deposit"], maps["deposit_solid"] +
                                                 maps["deposit_fluid"], rtol=0, atol=1e-12))
    wet = maps["deposit"] > 1e-3
    check("solid fraction = solid / mixture where wet",
          np.allclose(maps["solid_fraction"][wet], maps["deposit_solid"][wet] / maps["deposit"][wet],
                      rtol=1e-12, atol=0))
    check("solid fraction in [0, 1]", np.nanmin(maps["solid_fraction"]) >= 0 and
          np.nanmax(maps["solid_fraction"]) <= 1)
    # The summary's figures are the maps' (areas: cells above 1 cm).
    area = dx * dy
    check("max height", m["max_height_m"] == maps["max_height"].max())
    check("max pressure", abs(m["max_pressure_Pa"] - maps["max_pressure"].max()) < 1e-9)
    check("max solid speed", m["max_solid_speed_m_s"] == maps["max_solid_speed"].max())
    check("deposit area", abs(np.count_nonzero(maps["deposit"] > 0.01) * area -
                              m["deposit_area_m2"]) < 1e-6)
    check("affected area", abs(np.count_nonzero(maps["max_height"] > 0.01) * area -
                               m["affected_area_m2"]) < 1e-6)
    check("mixture pressure at least each phase's",
          bool(np.all(maps["max_pressure"] >= np.maximum(maps["max_solid_pressure"],
                                                         maps["max_fluid_pressure"]) - 1e-9)))
    arrival = maps["arrival_time"]
    check("arrival finite exactly where the mixture exceeded 1 cm",
          bool(np.array_equal(np.isfinite(arrival), maps["max_height"] > 0.01)))
    # series.csv: each phase's volume plus its outflow is the release.
    series = read_columns(os.path.join(out, "series.csv"))
    check("series solid volume kept", all(abs(v + o - 2750.0) < 1e-9 for v, o in
                                          zip(series["solid_volume"], series["solid_outflow"])))
    check("series ends at 60 s", abs(series["time"][-1] - 60.0) < 1e-6)
    # Snapshots every 10 s: seven times, four fields each.
    times = read_columns(os.path.join(out, "snapshots", "times.csv"))["time"]
    check("seven snapshot times", len(times) == 7)
    for field in ["height", "solid_fraction", "solid_speed", "fluid_speed"]:
        check(f"snapshot {field} written",
              os.path.exists(os.path.join(out, "snapshots", f"{field}_000006.tif")))
    res = subprocess.run(["/usr/bin/python3", os.path.join(src, "plots", "plot_runout2d.py"), out],
                         check=True, capture_output=True, text=True)
    pngs = [p for p in res.stdout.split() if p.endswith(".png")]
    check("plot_runout2d.py draws the seven two-phase maps", len(pngs) == 7)
    for p in pngs:
        with open(p, "rb") as f:
            check(f"{os.path.basename(p)} is a PNG", f.read(8) == b"\x89PNG\r\n\x1a\n")

check.finish("two-phase run")
