#!/usr/bin/env python3
"""Physics fingerprints of every bundled scenario, for refactors that must not
change results ("same bits before and after").

Runs each scenario of scenarios/ (every sub-folder) shortened with
--set run.duration=..., on one thread, and hashes what a run produced:
  final    the last snapshot of every .pvd (particles, points, membranes, walls)
           and every map that holds the end state (fv2d .npy/.asc/.tif)
  summary  summary.json without what is not physics (wall-clock times, rates,
           the talus version, the output path)
  series   series.csv and every other .csv the run wrote
  files    every other file, each by name

  record:  scenario_hashes.py BUILD/talus --record hashes.json
  check:   scenario_hashes.py BUILD/talus --check hashes.json [--only NAME,...]

check prints, per scenario, which of final / summary / series differ and exits
1 if an exit code or a final state differs. Series rows, and the summary
figures sampled at them (peaks, experiment curves), move when the output
schedule changes; those are reported, not failed.
"""
import argparse
import hashlib
import json
import os
import re
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENARIOS = os.path.join(ROOT, "scenarios")

# Short simulated durations: long enough for contacts, impacts and the
# experiments' stages to start, short enough for the whole set to run in a few
# minutes on two cores. Setup (packing, settling) always runs in full.
DURATION = {"dem": "0.01", "mpm": "0.02", "runout": "0.5"}
# Scenarios whose experiments refuse a run shorter than their protocol: run
# in full (None: no --set).
DURATION_BY_NAME = {"granular_beam_3pt_small": None, "granular_beam_4pt_small": None,
                    "granular_gripper_small": None}
# Not runnable with `talus run` (comparisons), or full-size versions of the
# small beam and gripper above (tens of minutes each).
SKIP = {"compare_flume_A", "granular_beam_3pt", "granular_gripper"}

# Summary keys that are not physics: timings and rates depend on the machine.
NOT_PHYSICS = re.compile(r"(_wall_s|_seconds|_per_s|^talus_version$|^output$|^threads$)")


def method_of(path):
    text = open(path).read()
    m = re.search(r'^method\s*=\s*"(\w+)"', text, re.M)
    if m:
        return m.group(1)
    m = re.search(r'^extends\s*=\s*"([^"]+)"', text, re.M)
    if m:
        return method_of(os.path.join(os.path.dirname(path), m.group(1)))
    return "dem"


def strip(obj):
    if isinstance(obj, dict):
        return {k: strip(v) for k, v in obj.items() if not NOT_PHYSICS.search(k)}
    if isinstance(obj, list):
        return [strip(v) for v in obj]
    return obj


def sha(data):
    return hashlib.sha256(data).hexdigest()[:16]


def last_frames(run):
    """The last file of every .pvd collection (the final state)."""
    out = {}
    for f in sorted(os.listdir(run)):
        if f.endswith(".pvd"):
            sets = ET.parse(os.path.join(run, f)).getroot().iter("DataSet")
            files = [d.get("file") for d in sets]
            if files:
                with open(os.path.join(run, files[-1]), "rb") as fh:
                    out[f] = sha(fh.read())
    return out


def fingerprint(run):
    fp = {"final": last_frames(run), "summary": "", "series": {}, "files": {}}
    for dirpath, _, names in os.walk(run):
        for n in sorted(names):
            p = os.path.join(dirpath, n)
            rel = os.path.relpath(p, run)
            if n == "summary.json":
                with open(p) as fh:
                    fp["summary"] = sha(json.dumps(strip(json.load(fh)), sort_keys=True).encode())
            elif n.endswith(".csv"):
                with open(p, "rb") as fh:
                    fp["series"][rel] = sha(fh.read())
            elif n.endswith((".npy", ".asc", ".tif")):
                with open(p, "rb") as fh:
                    fp["final"][rel] = sha(fh.read())
            elif n.endswith((".vtu", ".pvd", ".png", ".tmp", ".bin")) or n == "scenario.toml":
                continue  # frames via .pvd; plots, checkpoints and the resolved file are not physics
            else:
                with open(p, "rb") as fh:
                    fp["files"][rel] = sha(fh.read())
    return fp


def run_all(talus, only):
    results = {}
    # Keyed by name (the stem, as `talus run NAME`), from every sub-folder.
    paths = {f[:-5]: os.path.join(d, f) for d, _, fs in os.walk(SCENARIOS) for f in fs
             if f.endswith(".toml")}
    names = sorted(paths)
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            if name in SKIP or (only and name not in only):
                continue
            path = paths[name]
            method = method_of(path)
            dur = DURATION_BY_NAME.get(name, DURATION.get(method, "0.01"))
            out = os.path.join(tmp, name)
            cmd = [talus, "run", path, "--out", out, "--threads", "1", "--quiet"]
            if dur is not None:
                cmd += ["--set", "run.duration=" + dur]
            t0 = time.time()
            p = subprocess.run(cmd, capture_output=True, text=True)
            dt = time.time() - t0
            entry = {"method": method, "duration": dur, "exit": p.returncode}
            if os.path.isdir(out):
                entry.update(fingerprint(out))
            if p.returncode != 0:
                entry["stderr"] = p.stderr.strip().splitlines()[-1:] if p.stderr else []
            print(f"{name:34s} {method:7s} exit {p.returncode}  {dt:6.1f} s", flush=True)
            results[name] = entry
    return results


def compare(old, new):
    bad = False
    for name in sorted(set(old) | set(new)):
        a, b = old.get(name), new.get(name)
        if a is None or b is None:
            print(f"{name}: only in {'new' if a is None else 'recorded'}")
            continue
        diffs = [k for k in ("exit", "final", "summary", "series", "files") if a.get(k) != b.get(k)]
        if not diffs:
            print(f"{name}: same")
            continue
        hard = [k for k in diffs if k in ("exit", "final")]
        bad = bad or bool(hard)
        print(f"{name}: differs in {', '.join(diffs)}")
        for k in diffs:
            if isinstance(a.get(k), dict):
                for f in sorted(set(a[k]) | set(b.get(k, {}))):
                    if a[k].get(f) != b[k].get(f):
                        print(f"    {k}/{f}")
    return bad


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("talus")
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--record")
    g.add_argument("--check")
    ap.add_argument("--only", default="")
    a = ap.parse_args()
    only = set(filter(None, a.only.split(",")))
    new = run_all(os.path.abspath(a.talus), only)
    if a.record:
        with open(a.record, "w") as fh:
            json.dump(new, fh, indent=1, sort_keys=True)
        return 0
    with open(a.check) as fh:
        old = json.load(fh)
    if only:
        old = {k: v for k, v in old.items() if k in only}
    return 1 if compare(old, new) else 0


if __name__ == "__main__":
    sys.exit(main())
