#!/usr/bin/env bash
# talus compare on a coarse DEM flume (540 disks, 2 s) and the DAN flume: both
# run, the report carries each method's own numbers, the plots are drawn, and
# scenarios on different flumes are refused before anything runs.
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
data=$src/tests/data/scenarios

"$talus" compare "$data/compare_coarse.toml" --out "$tmp/cmp" --quiet >"$tmp/out" 2>&1; rc=$?
check_rc "compare exits 0" "$tmp/out"
check "each method ran into its folder" '[ -s "$tmp/cmp/dem/summary.json" ] && [ -s "$tmp/cmp/dan/summary.json" ]'
check "table printed and written" 'grep -q "| dem |" "$tmp/out" && grep -q "| dan |" "$tmp/cmp/comparison.md"'
/usr/bin/python3 - "$tmp/cmp" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import csv, json, sys
out = sys.argv[1]
c = json.load(open(out + "/comparison.json"))
dem = json.load(open(out + "/dem/summary.json"))["flume"]
dan = json.load(open(out + "/dan/summary.json"))["metrics"]
# The report repeats each method's own numbers.
assert c["methods"]["dem"]["arrival_at_barrier_s"] == dem["front"]["reach_barrier_time"]
assert c["methods"]["dem"]["runup_along_barrier_m"] == dem["runup"]["final_s"]
assert abs(c["methods"]["dem"]["runup_elevation_m"]
           - (dem["runup"]["final_height"] + dem["path"]["bed_low_y"])) < 1e-12
assert c["methods"]["dan"]["arrival_at_barrier_s"] == dan["barrier_arrival_time_s"]
assert c["methods"]["dan"]["deposit_tail_s_m"] == dan["tail_s_m"]
# One flume: the barrier starts where the DEM analysis says it does.
assert abs(c["barrier_start_s"] - dem["path"]["arc_end_s"]) < 1e-12
for m in ("dem", "dan"):
    rows = list(csv.DictReader(open(f"{out}/compare/front_{m}.csv")))
    assert len(rows) > 10, m
    assert float(rows[-1]["s"]) > c["barrier_start_s"], m  # both fronts reach the barrier
PY
check_rc "report matches each method's summary"
/usr/bin/python3 "$src/plots/plot_compare.py" "$tmp/cmp" >"$tmp/plots" 2>&1; rc=$?
check "plots drawn" '[ $rc -eq 0 ] && [ -s "$tmp/cmp/plots/compare_front.png" ] && [ -s "$tmp/cmp/plots/compare_deposit.png" ]'

"$talus" compare "$data/compare_coarse.toml" --methods dan --out "$tmp/only" --quiet >"$tmp/out" 2>&1; rc=$?
check "--methods dan runs only DAN" '[ $rc -eq 0 ] && [ ! -e "$tmp/only/dem" ] && [ -s "$tmp/only/dan/summary.json" ]'
"$talus" compare "$data/compare_mismatch.toml" --out "$tmp/mm" >"$tmp/out" 2>&1; rc=$?
check "different flumes refused before running (exit 2)" '[ $rc -eq 2 ] && grep -q "different flumes" "$tmp/out" && [ ! -e "$tmp/mm" ]'
"$talus" compare "$data/compare_coarse.toml" --methods mpm --out "$tmp/m" >"$tmp/out" 2>&1; rc=$?
check "a method the file does not list exits 2" '[ $rc -eq 2 ] && grep -q "mpm" "$tmp/out"'
"$talus" run "$data/compare_coarse.toml" --out "$tmp/r" >"$tmp/out" 2>&1; rc=$?
check "talus run on a comparison file says to use compare" '[ $rc -eq 2 ] && grep -q "talus compare" "$tmp/out"'

finish compare
