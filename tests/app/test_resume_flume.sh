#!/usr/bin/env bash
# A flume run (random fill, settling, gate removed at t = 0) killed after a
# checkpoint and resumed with --resume ends as the uninterrupted run: the
# resume takes particles, time step and critical step from the checkpoint
# (format 5) instead of filling the release triangle again, and the series,
# the flume's front and forces and the summary's resolved step are the same.
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
args=(run "$src/tests/data/scenarios/flume_A_coarse.toml" --quiet --threads 1
      --set "run.duration=0.9" --set "output.checkpoint_interval=0.15"
      --set "output.series_interval=0.01" --set "output.snapshot_interval=0.3")
"$talus" "${args[@]}" --out "$tmp/full" > "$tmp/py" 2>&1
rc=$?; check_rc "uninterrupted run"

"$talus" "${args[@]}" --out "$tmp/killed" & pid=$!
wait_for_checkpoint "$tmp/killed" $pid
check "the run is still going after its first checkpoint (else make it longer)" "kill -0 $pid 2>/dev/null"
kill -9 $pid; wait $pid 2>/dev/null
check "no summary before the resume" '[ ! -f "$tmp/killed/summary.json" ]'
"$talus" run --resume "$tmp/killed" --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "resume"

for f in series.csv flume/front.csv particles.pvd; do
  check "$f the same" 'cmp -s "$tmp/full/$f" "$tmp/killed/$f" || { diff "$tmp/full/$f" "$tmp/killed/$f" | head -4; false; }'
done
/usr/bin/python3 - "$tmp/full/summary.json" "$tmp/killed/summary.json" > "$tmp/py" 2>&1 <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
for key in ("time_step_s", "critical_time_step_s", "reference_impact_speed_m_s", "skin_m",
            "settle_time_s"):
    assert a["resolved"][key] == b["resolved"][key], (key, a["resolved"][key], b["resolved"][key])
assert a["resolved"]["settle_time_s"] > 0, a["resolved"]
assert a["flume"] == b["flume"], "the flume reports differ"
assert a["metrics"]["walls"] == b["metrics"]["walls"], "wall forces and impulses differ"
PY
rc=$?; check_rc "summary: resolved step, flume report and wall impulses the same"
finish "resume flume"
