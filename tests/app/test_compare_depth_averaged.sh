#!/usr/bin/env bash
# talus compare with the depth-averaged methods on flume A
# (scenarios/compare/compare_flume_A.toml --methods dan,fv2d,two_phase): the grid
# models run on the flume extruded into 3 rows of 5 mm cells and report the
# flume's figures as DAN does; the report repeats each method's own numbers,
# the two-phase model without fluid gives fv2d's figures, both reach and
# climb the barrier, and a grid scenario on a raster is refused before
# anything runs. Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"

"$talus" compare "$src/scenarios/compare/compare_flume_A.toml" --methods dan,fv2d,two_phase \
  --out "$tmp/cmp" --quiet -j 1 >"$tmp/out" 2>&1; rc=$?
check_rc "compare exits 0" "$tmp/out"
for m in dan fv2d two_phase; do
  check "$m ran into its folder" '[ -s "$tmp/cmp/'$m'/summary.json" ]'
  check "$m in the table" 'grep -q "| '$m' |" "$tmp/cmp/comparison.md"'
done
check "grid runs write the flume files" \
  '[ -s "$tmp/cmp/fv2d/front.csv" ] && [ -s "$tmp/cmp/fv2d/deposit.csv" ] && [ -s "$tmp/cmp/two_phase/path.csv" ]'
/usr/bin/python3 - "$tmp/cmp" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import csv, json, sys
out = sys.argv[1]
c = json.load(open(out + "/comparison.json"))
for m in ("dan", "fv2d", "two_phase"):
    s = json.load(open(f"{out}/{m}/summary.json"))["metrics"]
    r = c["methods"][m]
    # The report repeats each method's own numbers.
    assert r["arrival_at_barrier_s"] == s["barrier_arrival_time_s"], m
    assert r["final_front_s_m"] == s["front_s_m"], m
    assert r["runup_along_barrier_m"] == s["runup_final"]["distance_on_barrier_m"], m
    assert r["deposit_tail_s_m"] == s["tail_s_m"], m
    # Each front reaches the barrier (at s = 1.161 m) and climbs it.
    assert r["final_front_s_m"] > c["barrier_start_s"], (m, r)
    assert r["runup_along_barrier_m"] > 0.1, (m, r)
    rows = list(csv.DictReader(open(f"{out}/compare/front_{m}.csv")))
    assert len(rows) > 100, (m, len(rows))  # every 10 ms over 3 s
# Without fluid (rho_f = 0, alpha_s = 1) the two-phase model is fv2d's
# granular model (tests/runout/test_two_phase_run.cpp: depths equal to
# round-off), so the flume figures agree to round-off.
a, b = c["methods"]["fv2d"], c["methods"]["two_phase"]
for k in ("arrival_at_barrier_s", "final_front_s_m", "runup_along_barrier_m",
          "runup_elevation_m", "deposit_tail_s_m"):
    assert abs(a[k] - b[k]) < 1e-9, (k, a[k], b[k])
PY
check_rc "report matches each method's summary; two-phase without fluid is fv2d"
/usr/bin/python3 "$src/plots/plot_compare.py" "$tmp/cmp" >"$tmp/plots" 2>&1; rc=$?
check "plots drawn" '[ $rc -eq 0 ] && [ -s "$tmp/cmp/plots/compare_front.png" ]'

"$talus" compare "$src/tests/data/scenarios/compare_grid_on_raster.toml" --out "$tmp/r" >"$tmp/out" 2>&1; rc=$?
check "a grid scenario on a raster refused before running (exit 2)" \
  '[ $rc -eq 2 ] && grep -q "on a \[path\] of type \"flume\"" "$tmp/out" && [ ! -e "$tmp/r" ] || { cat "$tmp/out"; false; }'
finish compare_depth_averaged
