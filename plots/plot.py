#!/usr/bin/python3
"""The plots of one talus run folder, whatever it ran: one entry point for plots/.

Usage: plot.py RUN_DIR   (prints the path of every PNG written, one a line)

Reads RUN_DIR/summary.json ("method", "model" and the experiments' blocks) and runs
the plot scripts of this folder that fit, each as it is run on its own:
  method "dem"                  plot_run.py (energies, contacts, wall forces)
  method "mpm"                  plot_mpm.py; with membranes (membranes.csv)
                                plot_mpm_geotextile.py; with cohesion loss (a material's
                                critical_volume_strain) plot_clay_block.py
  method "runout", model "dan"  plot_dan.py
  model "fv2d" or "two_phase"   plot_runout2d.py (maps over the terrain); on a flume path
                                (front.csv, deposit.csv, path.csv, as DAN's) plot_dan.py
  block "flume" (DEM)           plot_flume.py
  block "triaxial", "hollow_sphere", "gripper"
                                plot_<block>.py RUN_DIR/plots/<block>.png RUN_DIR
  block "beam"                  three-point: plot_beam.py; "four_point":
                                plot_beam_four_point.py and plot_beam_force_network.py
                                (RUN_DIR/plots/<name>.png)
A `talus compare` folder (comparison.json, no summary.json) gets plot_compare.py.
The scripts that take OUT.png RUN_DIR... compare several runs when called directly;
here they get the one run. Exit status 1 if a script failed (the others still run),
2 if RUN_DIR holds neither summary.json nor comparison.json.
Uses Debian's matplotlib; run with /usr/bin/python3.
"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def has_cohesion_loss(summary):
    # summary["scenario"] is the resolved scenario ("resolved" holds run figures).
    materials = summary.get("scenario", {}).get("materials", [])
    return any(m.get("critical_volume_strain", 0) for m in materials if isinstance(m, dict))


def jobs_for(run, summary):
    """(script, arguments) of each plot that fits the run, in the order drawn."""
    method, model = summary.get("method"), summary.get("model")
    jobs = []
    if method == "dem":
        jobs.append(("plot_run.py", [run]))
    elif method == "mpm":
        jobs.append(("plot_mpm.py", [run]))
        if os.path.isfile(os.path.join(run, "membranes.csv")):
            jobs.append(("plot_mpm_geotextile.py", [run]))
        if has_cohesion_loss(summary):
            jobs.append(("plot_clay_block.py", [run]))
    elif method == "runout":
        # A grid model on a flume path writes DAN's files and gets DAN's
        # figures (both scripts would write plots/deposit.png).
        on_path = all(os.path.isfile(os.path.join(run, f))
                      for f in ("front.csv", "deposit.csv", "path.csv"))
        if model == "dan" or on_path:
            jobs.append(("plot_dan.py", [run]))
        else:
            jobs.append(("plot_runout2d.py", [run]))
    # The flume's pictures are of grains coloured by layer: DEM runs only (an
    # MPM flume's points are drawn by plot_mpm.py).
    if "flume" in summary and method == "dem":
        jobs.append(("plot_flume.py", [run]))
    out = os.path.join(run, "plots")
    for block in ("triaxial", "hollow_sphere", "gripper"):
        if block in summary:
            jobs.append((f"plot_{block}.py", [os.path.join(out, block + ".png"), run]))
    if "beam" in summary:
        if summary["beam"].get("test") == "four_point":
            for name in ("beam_four_point", "beam_force_network"):
                jobs.append((f"plot_{name}.py", [os.path.join(out, name + ".png"), run]))
        else:
            jobs.append(("plot_beam.py", [os.path.join(out, "beam.png"), run]))
    return jobs


def run_job(script, args):
    """Runs one script; returns the PNGs it wrote (named on its stdout or given as OUT.png)."""
    before = {a: os.path.getmtime(a) for a in args if a.endswith(".png") and os.path.isfile(a)}
    for a in args:
        if a.endswith(".png"):
            os.makedirs(os.path.dirname(a), exist_ok=True)
    p = subprocess.run([sys.executable, os.path.join(HERE, script)] + args,
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.stderr.write(f"plot.py: {script} failed (exit {p.returncode}):\n{p.stdout}{p.stderr}")
        return None
    pngs = [line.strip() for line in p.stdout.splitlines() if line.strip().endswith(".png")]
    for a in args:
        if a.endswith(".png") and os.path.isfile(a) and before.get(a) != os.path.getmtime(a):
            if a not in pngs:
                pngs.append(a)
    # What else a script prints (tables, fits) goes to stderr: stdout is the list of PNGs.
    rest = [line for line in p.stdout.splitlines() if line.strip() and line.strip() not in pngs]
    if rest:
        sys.stderr.write("".join(f"{script}: {line}\n" for line in rest))
    return pngs


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    run = sys.argv[1]
    summary_path = os.path.join(run, "summary.json")
    if os.path.isfile(summary_path):
        with open(summary_path) as f:
            jobs = jobs_for(run, json.load(f))
    elif os.path.isfile(os.path.join(run, "comparison.json")):
        jobs = [("plot_compare.py", [run])]
    else:
        sys.stderr.write(f"plot.py: {run}: neither summary.json nor comparison.json\n")
        sys.exit(2)
    failed = 0
    for script, args in jobs:
        pngs = run_job(script, args)
        if pngs is None:
            failed += 1
            continue
        for p in pngs:
            print(p)
    if not jobs:
        sys.stderr.write(f"plot.py: no plot script fits {run}\n")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
