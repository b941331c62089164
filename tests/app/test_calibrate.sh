#!/usr/bin/env bash
# talus calibrate on a coarse dam break (grains 4-8 mm, ~500 disks, 1 s): the
# machinery (one run per value, table, best value, errors) and one physical
# trend: the upper slope of the deposit steepens as the grain friction grows.
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
db=$src/scenarios/dem/dam_break.toml
coarse=(--set dam_break.release.radius_min=4e-3 --set dam_break.release.radius_max=8e-3
        --set dam_break.release.porosity=0.2 --set run.duration=1.0 --set output.snapshots=false
        --set dam_break.segment_length=0.05 --set dam_break.segments=2)
args=(-p materials.0.friction_angle --target dam_break.gamma_1=20 --target dam_break.gamma_2=25)

"$talus" calibrate "$db" "${args[@]}" --values 5,15,30 "${coarse[@]}" --out "$tmp/cal" --quiet \
  >"$tmp/out" 2>&1; rc=$?
check "calibrate exits 0" '[ $rc -eq 0 ]'
check "one run per value" '[ -s "$tmp/cal/run_00/summary.json" ] && [ -s "$tmp/cal/run_02/summary.json" ]'
check "table printed and written" 'grep -q "sum of abs. deviations" "$tmp/out" && [ -s "$tmp/cal/calibration.md" ]'
/usr/bin/python3 - "$tmp/cal" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import json, math, sys
cal = sys.argv[1]
j = json.load(open(cal + "/calibration.json"))
# The deviations are recomputed from each run's own summary.json.
dev = []
for k, v in enumerate(j["values"]):
    s = json.load(open(f"{cal}/run_{k:02d}/summary.json"))
    mu = s["scenario"]["materials"][0]["friction"]
    assert abs(math.degrees(math.atan(mu)) - v) < 1e-9, "trial value not applied"
    dev.append(abs(s["dam_break"]["gamma_1"] - 20) + abs(s["dam_break"]["gamma_2"] - 25))
assert all(abs(a - b) < 1e-9 for a, b in zip(dev, j["deviation_sum"])), (dev, j["deviation_sum"])
assert j["best_value"] == j["values"][dev.index(min(dev))]
# More grain friction, steeper upper slope (5 -> 30 deg).
g2 = j["targets"]["dam_break.gamma_2"]["measured"]
assert g2[0] < g2[2], g2
PY
check_rc "best value is the least deviation; slope steepens with friction"

"$talus" calibrate "$db" "${args[@]}" --values 5 "${coarse[@]}" --out "$tmp/cal" >"$tmp/out" 2>&1; rc=$?
check "existing output folder refused (exit 2)" '[ $rc -eq 2 ] && grep -q -- "--force" "$tmp/out"'
"$talus" calibrate "$db" -p materials.0.friction_angle --target gamma=abc --values 5 \
  --out "$tmp/c2" >"$tmp/out" 2>&1; rc=$?
check "bad target exits 2 naming it" '[ $rc -eq 2 ] && grep -q "gamma=abc" "$tmp/out"'
"$talus" calibrate "$db" -p materials.0.density --target dam_break.gamma_1=20 --values -5 \
  --out "$tmp/c3" >"$tmp/out" 2>&1; rc=$?
check "invalid trial value refused before running" '[ $rc -eq 2 ] && [ ! -e "$tmp/c3/run_00" ]'

finish calibrate
