#!/usr/bin/env bash
# An MPM run killed with SIGKILL and resumed with --resume ends in the same
# state as an uninterrupted run (cohesive points that lose cohesion, a rigid
# plate that turns): the final snapshots of the points and of the boundary
# particles and the series are byte-identical, and so are the headline
# metrics of summary.json. A resume without a checkpoint is refused.
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
scenario=$src/tests/data/scenarios/mpm_resume.toml
killed_and_resumed mpm "$scenario"
full=$tmp/mpm-full killed=$tmp/mpm

for f in particles boundary; do
  last=$(ls "$full"/${f}_*.vtu | tail -1 | xargs basename)
  check "final $f snapshot $last identical" 'cmp -s "$full/$last" "$killed/$last"'
  check "$f.pvd identical" 'cmp -s "$full/$f.pvd" "$killed/$f.pvd"'
done
check "series.csv identical" 'cmp -s "$full/series.csv" "$killed/series.csv" || { diff "$full/series.csv" "$killed/series.csv" | head -5; false; }'
/usr/bin/python3 - "$full" "$killed" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import json, sys
a, b = (json.load(open(d + "/summary.json")) for d in sys.argv[1:3])
assert a["metrics"] == b["metrics"], (a["metrics"], b["metrics"])
# The run exercises the state a checkpoint must carry: points lost cohesion.
assert a["metrics"]["cracked_points"] > 0, a["metrics"]
PY
check_rc "summary metrics identical, cohesion lost in the run"

# On two threads (the resume takes the run's two from its folder).
killed_and_resumed mpm_2 "$scenario" 2
check "two threads: series.csv identical" 'cmp -s "$tmp/mpm_2-full/series.csv" "$tmp/mpm_2/series.csv"'
/usr/bin/python3 - "$tmp/mpm_2-full" "$tmp/mpm_2" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import json, sys
a, b = (json.load(open(d + "/summary.json")) for d in sys.argv[1:3])
assert a["metrics"] == b["metrics"], (a["metrics"], b["metrics"])
PY
check_rc "two threads: summary metrics identical"
check "two threads: the resume ran on two" 'grep -q "resumed.*2 threads" "$tmp/mpm_2/log.txt"'

mkdir -p "$tmp/empty" && cp "$full/scenario.toml" "$tmp/empty/"
"$talus" run --resume "$tmp/empty" >"$tmp/out" 2>&1; rc=$?
check "resume without checkpoint exits 2" '[ $rc -eq 2 ] && grep -q "checkpoint" "$tmp/out"'
finish resume_mpm
