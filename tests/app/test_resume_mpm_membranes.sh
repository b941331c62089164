#!/usr/bin/env bash
# MPM runs with membranes killed with SIGKILL and resumed with --resume end in
# the same state as uninterrupted runs: a 2D bag (FE cables) falling onto a
# York hammock, and a 3D block falling onto a sheet of FE triangles. The
# final snapshots of the points and membranes, the series, membranes.csv and
# the summary's metrics (membrane peak tension included) are byte-identical.
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"

resume_case() {  # scenario name
  local scenario=$src/tests/data/scenarios/$1.toml out=$tmp/$1
  "$talus" run "$scenario" --quiet -j 1 --out "$out/full" || { echo "FAIL: $1 uninterrupted"; fail=$((fail+1)); return; }
  "$talus" run "$scenario" --quiet -j 1 --out "$out/killed" & pid=$!
  wait_for_checkpoint "$out/killed" $pid
  check "$1: the run is still going when it is killed (else make it longer)" 'kill -0 $pid 2>/dev/null'
  kill -9 $pid; wait $pid 2>/dev/null
  check "$1: the killed run had not finished" '[ ! -f "$out/killed/summary.json" ]'
  "$talus" run --resume "$out/killed" --quiet -j 1 >"$tmp/out" 2>&1; rc=$?
  check_rc "$1: resume exits 0" "$tmp/out"
  for f in particles membranes; do
    last=$(ls "$out/full"/${f}_*.vtu | tail -1 | xargs basename)
    check "$1: final $f snapshot $last identical" 'cmp -s "$out/full/$last" "$out/killed/$last"'
    check "$1: $f.pvd identical" 'cmp -s "$out/full/$f.pvd" "$out/killed/$f.pvd"'
  done
  for f in series membranes; do
    check "$1: $f.csv identical" 'cmp -s "$out/full/$f.csv" "$out/killed/$f.csv" || { diff "$out/full/$f.csv" "$out/killed/$f.csv" | head -5; false; }'
  done
  /usr/bin/python3 - "$out/full" "$out/killed" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import json, sys
a, b = (json.load(open(d + "/summary.json")) for d in sys.argv[1:3])
assert a["metrics"] == b["metrics"], (a["metrics"], b["metrics"])
# The membranes were loaded: their state mattered.
assert a["metrics"]["membrane_peak_tension_N_m"] > 0, a["metrics"]
PY
  check_rc "$1: summary metrics identical, membranes under tension"
}

resume_case mpm_resume_membranes
resume_case mpm_resume_membranes_3d
finish resume_mpm_membranes
