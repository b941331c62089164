#!/usr/bin/env bash
# A run killed with SIGKILL and resumed with --resume ends in the same state as
# an uninterrupted run: the final snapshot files are byte-identical.
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
args=(run "$src/scenarios/dem/column_collapse.toml" --quiet
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
# The summary's physics figures are the uninterrupted run's, also when the
# peaks (kinetic energy at 0.11 s, wall forces) lie before the checkpoint the
# run resumes from (issue 28 §2: they held the resumed part's only).
same_metrics() {  # two run folders
  /usr/bin/python3 - "$1/summary.json" "$2/summary.json" <<'PY'
import json, sys
a, b = (json.load(open(p))["metrics"] for p in sys.argv[1:3])
assert a == b, {k: (a[k], b.get(k)) for k in a if a[k] != b.get(k)}
PY
}
same_metrics "$tmp/full" "$tmp/killed" || { echo "FAIL: summary metrics differ"; exit 1; }
# On two threads the same, from checkpoints that fall between neighbour
# builds: the resume reuses the threads' chunk cut of the last build (it fixes
# the order in which forces are summed; issue 28 §2 found it made anew).
"$talus" "${args[@]}" --threads 2 --out "$tmp/full2" || { echo "FAIL: two-thread run"; exit 1; }
"$talus" "${args[@]}" --threads 2 --out "$tmp/killed2" & pid=$!
wait_for_checkpoint "$tmp/killed2" $pid
kill -0 $pid 2>/dev/null || { echo "FAIL: the two-thread run finished before it could be killed"; exit 1; }
kill -9 $pid; wait $pid 2>/dev/null
"$talus" run --resume "$tmp/killed2" --quiet || { echo "FAIL: two-thread resume"; exit 1; }
cmp -s "$tmp/full2/$last" "$tmp/killed2/$last" || { echo "FAIL: two-thread final snapshot differs"; exit 1; }
cmp -s "$tmp/full2/series.csv" "$tmp/killed2/series.csv" || { echo "FAIL: two-thread series.csv differs"; exit 1; }
same_metrics "$tmp/full2" "$tmp/killed2" || { echo "FAIL: two-thread summary metrics differ"; exit 1; }
# The floor vibrates: the work it does on the grains (walls[].work_J, part of
# the energy check's budget) must be carried across the resume too.
c2=(run "$src/scenarios/dem/collapse_2d.toml" --quiet --set "run.duration=0.4"
    --set "output.checkpoint_interval=0.2" --set "output.snapshots=false"
    --set "walls.0.motion={amplitude=0.001, frequency=20, direction=[0, 1]}")
"$talus" "${c2[@]}" --out "$tmp/full2d" || { echo "FAIL: uninterrupted 2D run"; exit 1; }
"$talus" "${c2[@]}" --out "$tmp/killed2d" & pid=$!
wait_for_checkpoint "$tmp/killed2d" $pid
kill -0 $pid 2>/dev/null || { echo "FAIL: the 2D run finished before it could be killed"; exit 1; }
kill -9 $pid; wait $pid 2>/dev/null
"$talus" run --resume "$tmp/killed2d" --quiet || { echo "FAIL: 2D resume"; exit 1; }
same_metrics "$tmp/full2d" "$tmp/killed2d" || { echo "FAIL: 2D summary peaks differ after resume"; exit 1; }
/usr/bin/python3 - "$tmp/killed2d/summary.json" <<'PY' || { echo "FAIL: the floor did no work"; exit 1; }
import json, sys
floor = next(w for w in json.load(open(sys.argv[1]))["metrics"]["walls"] if w["name"] == "floor")
assert floor["work_J"] != 0.0, floor
PY
echo "resume: 10 passed, 0 failed"
