#!/usr/bin/python3
"""A reduced flume run end to end (geometry A, Model 3, grains 4-8 mm instead of
1-2 mm: 540 disks, 2 s): the flume analysis is consistent with itself and with
statics. The full-size runs and their comparison with Kuen are in docs/validation.md.

Args: <talus binary> <source dir>. Run with Debian's /usr/bin/python3.
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

from checks import Checks

talus, src = sys.argv[1], sys.argv[2]
check = Checks()


# flume_A_model3.toml with the reduction above (tests/data/scenarios/flume_A_coarse.toml).
coarse = os.path.join(src, "tests", "data", "scenarios", "flume_A_coarse.toml")

with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "run")
    proc = subprocess.run([talus, "run", coarse, "--out", out, "--threads", "1"], check=True,
                          capture_output=True, text=True)
    summary = json.load(open(os.path.join(out, "summary.json")))
    f = summary["flume"]
    # The command line's headline repeats the summary's key numbers.
    b = f["forces"]["barrier"]
    check("the headline names arrival, tail and the barrier's peaks",
          f"at the barrier {f['front']['reach_barrier_time']:.3f} s" in proc.stderr
          and f"main deposit from s = {f['deposit']['tail_s']:.3f} m" in proc.stderr
          and f"{b['peak_step_fx']:.0f} N (single step)" in proc.stderr)
    with open(os.path.join(out, "flume", "front.csv")) as fh:
        rows = list(csv.DictReader(fh))
    with open(os.path.join(out, "series.csv")) as fh:
        series = list(csv.DictReader(fh))

    check("no grain lost", f["deposit"]["lost"] == 0 and f["deposit"]["particles"] == 540)
    check("one front row per series row", len(rows) == len(series))
    # Statics: at rest, the walls carry the whole weight (per metre of width).
    # The grains are still after 2 s: the kinetic energy is tiny against m g h.
    ke = float(series[-1]["kinetic_energy"])
    weight = f["deposit"]["weight_per_m"]
    check("at rest after 2 s", ke < 1e-4 * weight * 0.1)
    fy = sum(f["forces"][part]["final_fy"] for part in ("chute", "arc", "barrier"))
    check(f"wall forces carry the weight within 1 % ({fy:.1f} vs {-weight:.1f} N/m)",
          abs(fy + weight) < 0.01 * weight)
    # The impulse reported is the integral of the force rows (mean forces x interval).
    t = [float(r["time"]) for r in rows]
    integral = sum(float(rows[k]["barrier_fx"]) * (t[k] - t[k - 1]) for k in range(1, len(rows)))
    check("barrier impulse = integral of its force",
          abs(integral - f["forces"]["barrier"]["impulse_x"]) < 1e-6 * abs(integral) + 1e-9)
    # The order of events along the path.
    arc, barrier = f["front"]["reach_arc_time"], f["front"]["reach_barrier_time"]
    check("the front reaches the arc, then the barrier", 0 < arc < barrier < 2.0)
    check("no barrier force before the front gets there",
          all(abs(float(r["barrier_fx"])) < 1e-9 for r in rows if float(r["time"]) < arc))
    check("run-up is on the barrier and within its length",
          0 < f["runup"]["final_s"] <= f["runup"]["max_s"] + 1e-12
          and f["runup"]["max_s"] < f["path"]["path_end_s"] - f["path"]["arc_end_s"])
    check("the main deposit starts upstream of the barrier", f["deposit"]["tail_s"] < f["path"]["arc_end_s"])
    # The single-step peak of an interval bounds its mean (|mean of f| <= max |f|;
    # the 1e-9 N/m is round-off of the impulse difference).
    parts = ("chute", "arc", "barrier")
    check("each interval's single-step peak bounds its mean force",
          all(abs(float(r[f"{p}_f{c}_peak"])) >= abs(float(r[f"{p}_f{c}"])) - 1e-9
              for r in rows for p in parts for c in "xy"))
    check("the summary's single-step peaks are at least the peak means",
          all(abs(f["forces"][p][f"peak_step_f{c}"]) >= abs(f["forces"][p][f"peak_f{c}"])
              for p in parts for c in "xy"))
    frames = sorted(os.listdir(os.path.join(out, "flume", "frames")))
    check("a frame per snapshot (0, 0.5, ..., 2 s)", len(frames) == 5)
    plots = subprocess.run(["/usr/bin/python3", os.path.join(src, "plots", "plot_flume.py"), out],
                           capture_output=True, text=True)
    check("plots are drawn", plots.returncode == 0 and all(
        os.path.getsize(p) > 10000 for p in plots.stdout.split()))
    check("the force-peak plot is among them",
          any(p.endswith("flume_force_peaks.png") for p in plots.stdout.split()))

check.finish("flume run")
