#!/usr/bin/python3
"""Barrier impulse and peak force against contact stiffness, over several packings.

Feeds docs/validation/flume.md, sections "Full runs (3 s of flow; ...)" and "Time step:
..." (stiffness and packings); tests/app/test_flume_stiffness_run.py runs the same.

Usage: flume_stiffness.py TALUS SCENARIO OUT_DIR --stiffness 1e8,1e9 --seeds 1,2,3
                          [--threads N] [--series-interval S] [--until T1,T2,...]
                          [--set key=value ...]

Kuen (2011, §7.1, Abb. 41): a stiffer contact gives a shorter impact with a larger
peak force but the same impulse. One flume run is chaotic: two runs that differ only
by round-off end with barrier impulses 10 % apart (docs/validation.md), so one run
per stiffness cannot show a 5 % effect. This runs every (stiffness, seed) pair
(the seed changes the release packing), then compares the means over the seeds.
Stiffness is set for normal and shear, grains and walls (materials 0 and 1).
Peak = largest barrier force over the series rows, each the mean force over one
series interval (from the impulse columns; choose a short --series-interval);
peak_step = the largest barrier force of a single step.
--until adds the barrier's x impulse accumulated from the start up to each time T
(the row of series.csv at T), e.g. 1.4 for Kuen's time at which the forces settle:
the impulse of the impact, without the static load that follows it.
Prints one line per run and a markdown table of means and standard errors.
"""
import argparse
import csv
import json
import math
import os
import subprocess


def run_one(a, k, seed):
    out = os.path.join(a.out, f"k{k:g}_seed{seed}")
    sets = [f"materials.{m}.{kind}_stiffness={k:g}" for m in (0, 1) for kind in ("normal", "shear")]
    sets += [f"run.seed={seed}", f"output.series_interval={a.series_interval:g}",
             "output.snapshots=false", "output.checkpoint_interval=0"] + a.set
    cmd = [a.talus, "run", a.scenario, "--out", out, "--force", "--quiet", "--threads", str(a.threads)]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True)
    f = json.load(open(os.path.join(out, "summary.json")))["flume"]["forces"]
    b, arc = f["barrier"], f["arc"]
    r = {"impulse_x": b["impulse_x"], "impulse_y": b["impulse_y"],
         "arc_impulse_y": arc["impulse_y"], "peak_fx": b["peak_fx"],
         "peak_fx_time": b["peak_fx_time"], "final_fx": b["final_fx"],
         "peak_step_fx": b["peak_step_fx"], "peak_step_fx_time": b["peak_step_fx_time"]}
    r.update(impulse_until(os.path.join(out, "series.csv"), a.until, a.series_interval))
    return r


def impulse_until(series, times, interval):
    """Barrier x impulse at the series row of each time in `times`."""
    out = {}
    if not times:
        return out
    with open(series) as fh:
        rows = [(float(r["time"]), float(r["barrier_impulse_x"])) for r in csv.DictReader(fh)]
    for t in times:
        row = min(rows, key=lambda tr: abs(tr[0] - t))
        if abs(row[0] - t) > 0.5 * interval + 1e-9:
            raise SystemExit(f"{series}: no row within half a series interval of t = {t:g} s")
        out[f"impulse_x_to_{t:g}s"] = row[1]
    return out


def mean_se(v):
    m = sum(v) / len(v)
    if len(v) < 2:
        return m, float("nan")
    var = sum((x - m) ** 2 for x in v) / (len(v) - 1)
    return m, math.sqrt(var / len(v))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("talus")
    p.add_argument("scenario")
    p.add_argument("out")
    p.add_argument("--stiffness", default="1e8,1e9")
    p.add_argument("--seeds", default="1,2,3")
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--series-interval", type=float, default=5e-4)
    p.add_argument("--until", default="", help="times T [s]: barrier x impulse up to T")
    p.add_argument("--set", action="append", default=[])
    a = p.parse_args()
    a.until = [float(v) for v in a.until.split(",") if v]
    ks = [float(v) for v in a.stiffness.split(",")]
    seeds = [int(v) for v in a.seeds.split(",")]
    res = {}
    for k in ks:
        for s in seeds:
            r = run_one(a, k, s)
            res[(k, s)] = r
            print(f"k={k:g} seed={s} " + " ".join(f"{n}={v:.6g}" for n, v in r.items()), flush=True)
    names = ["impulse_x", "impulse_y", "arc_impulse_y", "peak_fx", "peak_step_fx", "final_fx"]
    names += [f"impulse_x_to_{t:g}s" for t in a.until]
    print("\n| stiffness [N/m] | runs | " + " | ".join(names) + " |")
    print("|---" * (len(names) + 2) + "|")
    means = {}
    for k in ks:
        cells = []
        for n in names:
            m, se = mean_se([res[(k, s)][n] for s in seeds])
            means[(k, n)] = m
            cells.append(f"{m:.1f} ± {se:.1f}")
        print(f"| {k:g} | {len(seeds)} | " + " | ".join(cells) + " |")
    for k in ks[1:]:
        print(f"\nmean at {k:g} over mean at {ks[0]:g}: " + ", ".join(
            f"{n} {means[(k, n)] / means[(ks[0], n)]:.3f}" for n in names))


if __name__ == "__main__":
    main()
