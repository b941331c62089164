#!/usr/bin/env bash
# The flume benchmark of issue 3: geometry A, Model 3, 9099 disks, 3 s of flow,
# target under 2 minutes on 2 cores (docs/performance.md, flume section).
# Usage: bench/flume.sh [BIN] [THREADS]   (defaults: build/talus, 2)
# Prints setup, loop and total wall seconds against the target, steps and
# neighbour builds, and the machine it ran on. Run it on a quiet machine: two
# threads that wait for each other by spinning slow down badly under load.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/talus} th=${2:-2}
out=${BENCH_DIR:-/tmp/talus_bench}/flume_A_model3_t$th
echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) CPUs, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
"$bin" run "$root/scenarios/dem/flume_A_model3.toml" --out "$out" --force --quiet --threads "$th" \
  --set "output.snapshots=false" --set "output.checkpoint_interval=0"
/usr/bin/python3 - "$out/summary.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
r = d["run"]
total = r["setup_wall_s"] + r["loop_wall_s"]
print(f"setup {r['setup_wall_s']:.1f} s + loop {r['loop_wall_s']:.1f} s = {total:.1f} s "
      f"({r['steps']} steps, {r['neighbour_builds']} neighbour builds, "
      f"{r['particle_steps_per_s']:.3g} particle-steps/s); target 120 s: "
      f"{'met' if total < 120 else 'not met'}")
PY
