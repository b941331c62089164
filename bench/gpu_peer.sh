#!/usr/bin/env bash
# Particle-steps per second of the peer column on the GPU backend and on the
# CPU stepper with all cores, in one sitting (issue 35; docs/performance.md).
# Usage: bench/gpu_peer.sh [BUILD_DIR] [CPU_THREADS]   (default build, nproc)
# Cases (nx ny nz = grains):
#  - the peer case itself, 20 x 10 x 40 = 8 000 grains, its whole 60 000 steps
#    (0.3 s): throughput, and front and kinetic energy against the peer README
#    §4 ranges (front 0.17-0.18 m, KE ~6e-4 J) and the CPU;
#  - 200 x 50 x 100 = 10^6 and 400 x 250 x 100 = 10^7 grains, 100 layers high:
#    3 000 steps (15 ms) let the column close its lattice gaps (0.01 mm a
#    layer) and start to slump, then the timed steps.
# Both GPU pair loops are timed (TALUS_GPU_PAIR_LOOP = pair | row, docs/gpu.md);
# lines with TALUS_GPU_PHASES=1 add where the GPU time goes (events around
# each phase: those runs' own throughput is lower).
set -uo pipefail
bin=${1:-build}/bench/bench_gpu_peer
cpu=${2:-$(nproc)}
run() { echo "+ $*" >&2; "$bin" "$@"; }
for loop in pair row; do
  export TALUS_GPU_PAIR_LOOP=$loop
  echo "== pair loop: $loop"
  run 20 10 40 0 60000 gpu
  run 200 50 100 3000 2000 gpu
  TALUS_GPU_PHASES=1 run 200 50 100 3000 500 gpu
done
unset TALUS_GPU_PAIR_LOOP
echo "== CPU, $cpu threads"
run 20 10 40 0 60000 cpu "$cpu"
run 200 50 100 3000 200 cpu "$cpu"
echo "== 10^7 grains"
run 400 250 100 3000 300 gpu
TALUS_GPU_PAIR_LOOP=row run 400 250 100 3000 300 gpu
