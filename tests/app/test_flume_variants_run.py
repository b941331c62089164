#!/usr/bin/python3
"""Kuen's statements about the flume variants, on the reduced flume (geometry A,
grains 4-8 mm instead of 1-2 mm: 540 disks, 2 s; tests/data/scenarios/flume_A_coarse.toml),
each variant over three release packings (run.seed 1-3), compared by their means:

- Model 3: the front reaches the barrier at 0.8 +- 0.1 s (Kuen §7.2; flume.md "What was
  observed"), in every packing.
- Model 2 (rolling resistance at the walls only) "spreads out almost flat, like a liquid"
  (Kuen §5.2): fewer grains stay on the chute and the front runs further up the barrier
  than in Model 3.
- Deleting the gate or lifting it at 2.25 m/s gives "no significant difference" (Kuen's
  variants I and II): grains left on the chute within 5 % and run-up within 15 % of each
  other. The bounds are three times the packing-to-packing spread of a difference of two
  three-packing means, measured over six packings of each variant (2026-11-27: grains on
  the chute sd 6 of ~391, run-up sd 0.019 of ~0.32 m); the means measured differ by 0.4 %
  and 3.5 %.

What the reduced flume does not reproduce is not asserted here (Model 1 against Model 3,
the deposit's tail, particle size): see docs/validation.md.
Args: <talus binary> <source dir>. Run with Debian's /usr/bin/python3.
"""
import json
import os
import subprocess
import sys
import tempfile

from checks import Checks

talus, src = sys.argv[1], sys.argv[2]
coarse = os.path.join(src, "tests", "data", "scenarios", "flume_A_coarse.toml")
variants = {
    "model3": [],
    "model2": ["--set", "contact.kuen_particle_factor=1.0"],
    "lift": ["--set", "flume.gate=lift"],
}
seeds = (1, 2, 3)
check = Checks(show_passed=True)


with tempfile.TemporaryDirectory() as tmp:
    flume = {}
    for name, sets in variants.items():
        for seed in seeds:
            out = os.path.join(tmp, f"{name}_{seed}")
            subprocess.run([talus, "run", coarse, "--out", out, "--quiet", "--threads", "1",
                            "--set", f"run.seed={seed}", "--set", "output.snapshots=false"]
                           + sets, check=True)
            flume.setdefault(name, []).append(
                json.load(open(os.path.join(out, "summary.json")))["flume"])


def mean(name, get):
    return sum(get(f) for f in flume[name]) / len(flume[name])


def on_chute(f):
    return f["deposit"]["on_chute"]


def runup(f):
    return f["runup"]["final_s"]


arrivals = [f["front"]["reach_barrier_time"] for f in flume["model3"]]
check(f"Model 3 reaches the barrier at 0.8 +- 0.1 s ({', '.join(f'{t:.3f}' for t in arrivals)})",
      all(0.7 <= t <= 0.9 for t in arrivals))
m2, m3 = mean("model2", on_chute), mean("model3", on_chute)
check(f"Model 2 leaves fewer grains on the chute than Model 3 ({m2:.0f} vs {m3:.0f})", m2 < m3)
m2, m3 = mean("model2", runup), mean("model3", runup)
check(f"Model 2 runs further up the barrier than Model 3 ({m2:.3f} vs {m3:.3f} m)", m2 > m3)
lift, delete = mean("lift", on_chute), mean("model3", on_chute)
check(f"gate lifted or deleted: grains on the chute within 5 % ({lift:.0f} vs {delete:.0f})",
      abs(lift - delete) <= 0.05 * delete)
lift, delete = mean("lift", runup), mean("model3", runup)
check(f"gate lifted or deleted: run-up within 15 % ({lift:.3f} vs {delete:.3f} m)",
      abs(lift - delete) <= 0.15 * delete)

check.finish("flume variants")
