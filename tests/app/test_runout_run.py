#!/usr/bin/python3
"""The runout scenarios end to end through the talus binary: the 1D DAN flume
(scenarios/runout/runout_flume_A.toml, full length: 0.1 s of wall time) and the 2D
terrain run (scenarios/runout/runout_terrain_2d.toml, 40 s of its 150 s). Checks the
files and fields a user reads, that they are consistent with each other, and
that the plot scripts (plots/plot_dan.py, plots/plot_runout2d.py) write PNGs.

Args: <talus binary> <source dir>. Run with Debian's /usr/bin/python3.
"""
import json
import math
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


def run(scenario, out, *sets):
    args = [talus, "run", os.path.join(src, "scenarios", "runout", scenario), "--out", out, "-q", "--threads", "1"]
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True)
    return json.load(open(os.path.join(out, "summary.json")))


def plots(script, out):
    res = subprocess.run(["/usr/bin/python3", os.path.join(src, "plots", script), out],
                         check=True, capture_output=True, text=True)
    pngs = [p for p in res.stdout.split() if p.endswith(".png")]
    check(f"{script} writes PNGs", len(pngs) >= 2)
    for p in pngs:
        with open(p, "rb") as f:
            check(f"{p} is a PNG", f.read(8) == b"\x89PNG\r\n\x1a\n")
        check(f"{p} is not empty", os.path.getsize(p) > 5000)


with tempfile.TemporaryDirectory() as tmp:
    # --- 1D DAN flume, geometry A ---
    out = os.path.join(tmp, "flume")
    s = run("runout_flume_A.toml", out)
    m = s["metrics"]
    check("dan status", s["status"] == "completed" and s["model"] == "dan")
    # 0.07714 m^2 per metre of width at 1630 kg/m^3 (flume.md): 125.75 kg.
    check("dan volume", abs(m["volume_m3"] - 0.0771492) < 1e-6)
    check("dan mass", abs(m["mass_kg"] - 1630 * m["volume_m3"]) < 1e-9 * m["mass_kg"])
    # The front climbs the barrier (it starts at s = 1.161 m) but stays below its top.
    ru = m["runup_max"]
    check("dan run-up on the barrier", ru["distance_on_barrier_m"] > 0 and
          ru["s_m"] < s["resolved"]["path_s_end_m"])
    check("final run-up not above max", m["runup_final"]["elevation_m"] <= ru["elevation_m"] + 1e-12)
    check("dan came to rest", math.isfinite(m["rest_time_s"]) and m["kinetic_energy_J"] == 0.0)
    series = read_columns(os.path.join(out, "series.csv"))
    check("series columns", {"time", "front_s", "mass", "volume", "kinetic_energy"} <= set(series))
    check("series mass constant", max(series["mass"]) - min(series["mass"]) < 1e-9 * m["mass_kg"])
    check("series ends at the rest time", abs(series["time"][-1] - m["rest_time_s"]) < 1e-9)
    check("series front = summary front", abs(series["front_s"][-1] - m["front_s_m"]) < 1e-12)
    front = read_columns(os.path.join(out, "front.csv"))
    check("front starts at the gate", abs(front["s"][0]) < 1e-9 and front["time"][0] == 0.0)
    check("front reaches the max run-up", abs(max(front["s"]) - ru["s_m"]) < 0.01)
    deposit = read_columns(os.path.join(out, "deposit.csv"))
    check("one deposit row per block", len(deposit["s"]) == s["resolved"]["boundary_blocks"])
    check("deposit depths >= 0", min(deposit["depth"]) >= 0.0)
    path = read_columns(os.path.join(out, "path.csv"))
    check("path spans the blocks", path["s"][0] <= deposit["s"][0] and path["s"][-1] >= deposit["s"][-1])
    plots("plot_dan.py", out)

    # --- 2D terrain run (fv2d), shortened ---
    out = os.path.join(tmp, "terrain")
    s = run("runout_terrain_2d.toml", out, "run.duration=40")
    m, r = s["metrics"], s["resolved"]
    check("fv2d status", s["status"] == "completed" and s["model"] == "fv2d")
    check("fv2d ran 40 s", abs(s["run"]["simulated_time_s"] - 40.0) < 1e-9)
    check("fv2d volume", m["volume_error_relative"] < 1e-12 and
          abs(m["volume_m3"] + m["outflow_volume_m3"] - m["released_volume_m3"]) < 1e-9 * m["released_volume_m3"])
    series = read_columns(os.path.join(out, "series.csv"))
    check("fv2d series columns", {"time", "volume", "max_speed", "max_height"} <= set(series))
    check("fv2d series to 40 s", abs(series["time"][-1] - 40.0) < 1e-9)
    check("fv2d peak speed = max over series", max(series["max_speed"]) <= m["max_speed_m_s"] + 1e-9)
    shape = (r["cells_y"], r["cells_x"])
    dx, dy = r["cell_size_m"]
    arrays = {}
    for name in ("max_height", "max_speed", "max_pressure", "deposit", "elevation"):
        check(f"{name}.tif written", os.path.getsize(os.path.join(out, name + ".tif")) > 0)
        a = np.load(os.path.join(out, name + ".npy"))
        arrays[name] = a
        check(f"{name}.npy shape", a.shape == shape)
        check(f"{name}.npy finite", bool(np.all(np.isfinite(a))))
    check("max height >= deposit", bool(np.all(arrays["max_height"] >= arrays["deposit"] - 1e-12)))
    check("max height = summary", abs(arrays["max_height"].max() - m["max_height_m"]) < 1e-9)
    check("max pressure = rho v^2", abs(arrays["max_pressure"].max() - 2000 * arrays["max_speed"].max() ** 2)
          < 1e-6 * arrays["max_pressure"].max())
    # Areas count cells deeper than 1 cm (app/summary.cpp), deposit and maxima
    # bed-normal.
    check("deposit area", abs(np.count_nonzero(arrays["deposit"] > 0.01) * dx * dy - m["deposit_area_m2"]) < 1e-6)
    check("affected area", abs(np.count_nonzero(arrays["max_height"] > 0.01) * dx * dy - m["affected_area_m2"]) < 1e-6)
    # Arrival time: when a cell's bed-normal height first exceeded the same
    # 1 cm, from the same observations as the maxima; NaN (the GeoTIFF's
    # no-data value) where it never did, 0 in the release.
    check("arrival_time.tif written", os.path.getsize(os.path.join(out, "arrival_time.tif")) > 0)
    arrival = np.load(os.path.join(out, "arrival_time.npy"))
    check("arrival_time.npy shape", arrival.shape == shape)
    check("arrival finite exactly where the flow exceeded 1 cm",
          bool(np.array_equal(np.isfinite(arrival), arrays["max_height"] > 0.01)))
    reached = arrival[np.isfinite(arrival)]
    check("arrival from 0 (the release) to the end", reached.min() == 0.0 and reached.max() <= 40.0)
    check("arrival later than the start somewhere", bool(np.any(reached > 1.0)))
    # Cut at 40 s the avalanche still moves: the summary says so.
    check("fv2d warns that the mass still moves", not m["at_rest"] and
          any("still moving at the end" in w for w in s.get("warnings", [])))
    plots("plot_runout2d.py", out)

    # --- the whole 2D run: it ends by RAMMS' rule and reaches its barrier ---
    out = os.path.join(tmp, "terrain_full")
    s = run("runout_terrain_2d.toml", out)
    m = s["metrics"]
    check("fv2d stopped by the momentum rule before its 150 s, without a warning",
          m["stopped_by_momentum"] and s["run"]["simulated_time_s"] < 150.0 and not s.get("warnings"))
    with open(os.path.join(out, "log.txt")) as f:
        check("the headline says why it stopped",
              "stopped at t = 74.5 s: momentum below 1 % of its peak" in f.read())
    # The rule (run.stop_momentum_fraction = 0.01): every row after the peak
    # keeps at least 1 % of the peak momentum, the last (at the stop) less.
    series = read_columns(os.path.join(out, "series.csv"))
    momentum, peak = series["momentum_sum"], m["peak_momentum_kg_m_s"]
    check("series peak momentum within the summary's", max(momentum) <= peak)
    after = momentum[momentum.index(max(momentum)):]
    check("momentum >= 1 % of the peak until the stop",
          all(p >= 0.01 * peak for p in after[:-1]) and after[-1] < 0.01 * peak)
    # The barrier: 4 m high at x = 265-275 m, y = 50-200 m (make_runout_terrain.py),
    # i.e. columns 53-54 and rows 10-39 (rows run north to south, 50 of 5 m).
    arrival = np.load(os.path.join(out, "arrival_time.npy"))
    height = np.load(os.path.join(out, "max_height.npy"))
    on_barrier = arrival[10:40, 53:55]
    check("the flow reaches the barrier", bool(np.any(np.isfinite(on_barrier))))
    check("and spills over it", bool(np.any(height[10:40, 55:] > 0.01)))

check.finish("runout run")
