#!/usr/bin/env bash
# An MPM run killed with SIGKILL and resumed with --resume ends in the same
# state as an uninterrupted run (cohesive points that lose cohesion, a rigid
# plate that turns): the final snapshots of the points and of the boundary
# particles and the series are byte-identical, and so are the headline
# metrics of summary.json. A resume without a checkpoint is refused.
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
scenario=$src/tests/data/scenarios/mpm_resume.toml
"$talus" run "$scenario" --quiet -j 1 --out "$tmp/full" || { echo "FAIL: uninterrupted run"; exit 1; }

"$talus" run "$scenario" --quiet -j 1 --out "$tmp/killed" & pid=$!
wait_for_checkpoint "$tmp/killed" $pid
check "the run is still going when it is killed (else make it longer)" 'kill -0 $pid 2>/dev/null'
kill -9 $pid; wait $pid 2>/dev/null
check "a checkpoint was written" '[ -f "$tmp/killed/checkpoint.bin" ]'
check "the killed run had not finished" '[ ! -f "$tmp/killed/summary.json" ]'
"$talus" run --resume "$tmp/killed" --quiet -j 1 >"$tmp/out" 2>&1; rc=$?
check_rc "resume exits 0" "$tmp/out"

for f in particles boundary; do
  last=$(ls "$tmp/full"/${f}_*.vtu | tail -1 | xargs basename)
  check "final $f snapshot $last identical" 'cmp -s "$tmp/full/$last" "$tmp/killed/$last"'
  check "$f.pvd identical" 'cmp -s "$tmp/full/$f.pvd" "$tmp/killed/$f.pvd"'
done
check "series.csv identical" 'cmp -s "$tmp/full/series.csv" "$tmp/killed/series.csv" || { diff "$tmp/full/series.csv" "$tmp/killed/series.csv" | head -5; false; }'
/usr/bin/python3 - "$tmp/full" "$tmp/killed" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import json, sys
a, b = (json.load(open(d + "/summary.json")) for d in sys.argv[1:3])
assert a["metrics"] == b["metrics"], (a["metrics"], b["metrics"])
# The run exercises the state a checkpoint must carry: points lost cohesion.
assert a["metrics"]["cracked_points"] > 0, a["metrics"]
PY
check_rc "summary metrics identical, cohesion lost in the run"

mkdir -p "$tmp/empty" && cp "$tmp/full/scenario.toml" "$tmp/empty/"
"$talus" run --resume "$tmp/empty" >"$tmp/out" 2>&1; rc=$?
check "resume without checkpoint exits 2" '[ $rc -eq 2 ] && grep -q "checkpoint" "$tmp/out"'
finish resume_mpm
