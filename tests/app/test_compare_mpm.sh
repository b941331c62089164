#!/usr/bin/env bash
# talus compare with the MPM on the flume: a coarse MPM flume A (806 points,
# 20 mm grid, 1.2 s) and the DAN flume. The MPM runs, the report carries its
# own numbers, its front reaches the barrier, and an MPM scenario without a
# [flume] is refused before anything runs.
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
data=$src/tests/data/scenarios

"$talus" compare "$data/compare_mpm_coarse.toml" --out "$tmp/cmp" --quiet -j 1 >"$tmp/out" 2>&1; rc=$?
check_rc "compare exits 0" "$tmp/out"
check "table has the MPM row" 'grep -q "| mpm |" "$tmp/cmp/comparison.md"'
/usr/bin/python3 - "$tmp/cmp" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import csv, json, sys
out = sys.argv[1]
c = json.load(open(out + "/comparison.json"))
s = json.load(open(out + "/mpm/summary.json"))
f = s["flume"]
m = c["methods"]["mpm"]
# The report repeats the MPM run's own numbers.
assert m["arrival_at_barrier_s"] == f["front"]["reach_barrier_time"]
assert m["final_front_s_m"] == f["front"]["final_s"]
assert m["runup_along_barrier_m"] == f["runup"]["final_s"]
assert abs(m["runup_elevation_m"] - (f["runup"]["final_height"] + f["path"]["bed_low_y"])) < 1e-12
assert m["deposit_tail_s_m"] == f["deposit"]["tail_s"]
assert abs(c["barrier_start_s"] - f["path"]["arc_end_s"]) < 1e-12
# No point is lost: the release's 806 points (release triangle on the 10 mm
# lattice of 2 x 2 points per 20 mm cell) are all still counted.
assert f["deposit"]["points"] == 806 == s["metrics"]["points"], f["deposit"]
rows = list(csv.DictReader(open(out + "/compare/front_mpm.csv")))
assert len(rows) > 100
assert float(rows[-1]["s"]) > c["barrier_start_s"]  # the front reached the barrier
# The front never runs higher than the energy of the release allows: the
# run-up elevation stays below the top of the release (y = 1.115 m).
assert m["runup_elevation_m"] < 1.115
# flume.md "What was observed": at 0.8 s the first particles have passed the
# arc and reached the barrier. Tolerance +-0.1 s, the one the DEM's check uses
# (docs/validation.md, flume A) -- not fitted to this run, but written after
# it had given 0.730 s (DAN gives 0.354 s), which the reader should know.
assert abs(m["arrival_at_barrier_s"] - 0.8) <= 0.1, m["arrival_at_barrier_s"]
PY
check_rc "report matches the MPM summary; front on the barrier at the lab's arrival time"
/usr/bin/python3 "$src/plots/plot_compare.py" "$tmp/cmp" >"$tmp/plots" 2>&1; rc=$?
check "plots drawn with the MPM" '[ $rc -eq 0 ] && [ -s "$tmp/cmp/plots/compare_front.png" ] && [ -s "$tmp/cmp/compare/surface_mpm.csv" ]'

root=$(cd "$src" && pwd)  # the comparison file lives in $tmp: absolute paths
cat >"$tmp/noflume.toml" <<TOML
method = "compare"
name = "no_flume"
[methods]
mpm = "$root/tests/data/scenarios/mpm_resume.toml"
dan = "$root/scenarios/runout/runout_flume_A.toml"
TOML
"$talus" compare "$tmp/noflume.toml" --out "$tmp/nf" >"$tmp/out" 2>&1; rc=$?
check "MPM scenario without [flume] refused before running (exit 2)" '[ $rc -eq 2 ] && grep -q "needs a \[flume\]" "$tmp/out" && [ ! -e "$tmp/nf" ]'
finish compare_mpm
