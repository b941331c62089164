#!/usr/bin/env bash
# Repeatable cost proxy for the peer case: instruction count (callgrind) of
# STEPS steps resumed from a checkpoint at t = 0.12 s (peak kinetic energy,
# ~2.75 contacts per particle), one thread. Wall-clock times on a shared
# machine are noisy; instruction counts are not.
#
# Usage: bench/callgrind.sh [STEPS]      (default 500)
# Prints the total instruction count and the top functions.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
steps=${1:-500}
talus=${TALUS_BIN:-$root/build/talus}
work=${BENCH_DIR:-/tmp/talus_callgrind}
mkdir -p "$work"
ck=$work/checkpoint_0.12
if [ ! -f "$ck/checkpoint.bin" ]; then
  "$talus" run "$root/scenarios/dem/column_collapse.toml" --out "$ck" --force --quiet --threads 1 \
    --set run.duration=0.121 --set output.checkpoint_interval=0.06 \
    --set output.snapshots=false --set output.series_interval=0.121
fi
run=$work/resume
rm -rf "$run" && cp -r "$ck" "$run"
end=$(awk -v s="$steps" 'BEGIN{printf "%.10g", 0.12 + s*5e-6}')
sed -i -e "s/^duration = .*/duration = $end/" -e "s/^checkpoint_interval = .*/checkpoint_interval = 0.0/" \
  -e "s/^series_interval = .*/series_interval = 1.0/" "$run/scenario.toml"
OMP_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" \
  "$talus" run --resume "$run" --quiet --threads 1 2>"$work/valgrind.log"
grep -o '"steps": [0-9]*' "$run/summary.json" || true
callgrind_annotate "$work/callgrind.out" 2>/dev/null | sed -n '/PROGRAM TOTALS/p;/file:function/,+12p' | cut -c1-200
