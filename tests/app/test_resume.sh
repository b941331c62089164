#!/usr/bin/env bash
# A run killed with SIGKILL and resumed with --resume ends in the same state as
# an uninterrupted run: the final snapshot files are byte-identical.
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
args=(run "$src/scenarios/column_collapse.toml" --quiet
      --set "run.duration=0.04" --set "particles.0.box={min=[0,0,0],max=[0.0201,0.0201,0.0402]}"
      --set "output.snapshot_interval=0.01" --set "output.checkpoint_interval=0.002"
      --set "output.series_interval=0.001")
"$talus" "${args[@]}" --out "$tmp/full" || { echo "FAIL: uninterrupted run"; exit 1; }

"$talus" "${args[@]}" --out "$tmp/killed" & pid=$!
wait_for_checkpoint "$tmp/killed" $pid
if ! kill -0 $pid 2>/dev/null; then
  echo "FAIL: the run finished before it could be killed; make it longer"; exit 1
fi
kill -9 $pid; wait $pid 2>/dev/null
[ -f "$tmp/killed/checkpoint.bin" ] || { echo "FAIL: no checkpoint written"; exit 1; }
[ -f "$tmp/killed/summary.json" ] && { echo "FAIL: killed run already complete"; exit 1; }
"$talus" run --resume "$tmp/killed" --quiet || { echo "FAIL: resume"; exit 1; }

last=$(ls "$tmp/full"/particles_*.vtu | tail -1 | xargs basename)
cmp -s "$tmp/full/$last" "$tmp/killed/$last" || { echo "FAIL: final snapshot $last differs"; exit 1; }
cmp -s "$tmp/full/series.csv" "$tmp/killed/series.csv" || { echo "FAIL: series.csv differs"; diff "$tmp/full/series.csv" "$tmp/killed/series.csv" | head; exit 1; }
cmp -s "$tmp/full/particles.pvd" "$tmp/killed/particles.pvd" || { echo "FAIL: pvd differs"; exit 1; }
echo "resume: 4 passed, 0 failed"
