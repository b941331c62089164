"""What stepping from Python one step at a time costs against run(): the peer
column collapse (bench/peer_talus.sh's 20 x 10 x 40 = 8000 grains), the same
steps both ways, alternately, in one process (docs/performance.md).

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/python_step_overhead.py
           [STEPS=3000] [ROUNDS=3] [THREADS=1]
Prints the wall time of each way per round and the overhead of step(1).
"""
import os
import sys
import tempfile
import time

import talus

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
steps = int(sys.argv[1]) if len(sys.argv) > 1 else 3000
rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 3
threads = int(sys.argv[3]) if len(sys.argv) > 3 else 1

a, nx, ny, nz = 0.00201, 20, 10, 40
lx, ly, lz = nx * a, ny * a, nz * a
duration = steps * 5e-6
overrides = {
    "run.duration": duration * 2,  # the timed steps end before the run does
    "run.domain.min": [0, 0, 0],
    "run.domain.max": [6 * lx, ly, 1.5 * lz],
    "particles.0.box.min": [0, 0, 0],
    "particles.0.box.max": [lx, ly, lz],
    "walls.3.point": [0, ly, 0],
    "output.snapshots": False,
    "output.checkpoint_interval": 0,
    "output.series_interval": duration * 2,
}
scenario = os.path.join(ROOT, "scenarios", "dem", "column_collapse.toml")


def timed(folder, one_at_a_time):
    with tempfile.TemporaryDirectory() as tmp:
        run = talus.Run(scenario, out=os.path.join(tmp, folder), force=True, threads=threads,
                        overrides=overrides)
        run.step(10)  # the first neighbour build and start outside the timing
        t0 = time.perf_counter()
        if one_at_a_time:
            for _ in range(steps):
                run.step(1)
        else:
            run.step(steps)
        wall = time.perf_counter() - t0
        run.finish()
        return wall


for k in range(rounds):
    whole = timed("whole", False)
    single = timed("single", True)
    print(f"round {k + 1}: step({steps}) {whole:.3f} s, {steps} x step(1) {single:.3f} s, "
          f"overhead {100 * (single / whole - 1):+.1f} %", flush=True)
