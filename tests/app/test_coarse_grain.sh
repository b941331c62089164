#!/usr/bin/env bash
# talus analyse coarse-grain on tiny runs: grains drifting at a known velocity give that
# velocity in every cell with mass; the cells share out the grains' volume; bad input exits 2.
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
dem_list_scenario drift 3 "[0, 0, 0]" > "$tmp/drift.toml" <<'LIST'
  { position = [0.001, 0.001, 0.001], radius = 7e-4, velocity = [0.02, -0.01, 0.1] },
  { position = [0.003, 0.001, 0.001], radius = 6e-4, velocity = [0.02, -0.01, 0.1] },
  { position = [0.001, 0.003, 0.001], radius = 7e-4, velocity = [0.02, -0.01, 0.1] },
  { position = [0.003, 0.003, 0.001], radius = 5e-4, velocity = [0.02, -0.01, 0.1] },
  { position = [0.001, 0.001, 0.003], radius = 7e-4, velocity = [0.02, -0.01, 0.1] },
  { position = [0.003, 0.001, 0.003], radius = 7e-4, velocity = [0.02, -0.01, 0.1] },
  { position = [0.001, 0.003, 0.003], radius = 6e-4, velocity = [0.02, -0.01, 0.1] },
  { position = [0.003, 0.003, 0.003], radius = 7e-4, velocity = [0.02, -0.01, 0.1] },
LIST
run_check "tiny drift run" "$tmp/drift.toml" "$tmp/drift"
"$talus" analyse coarse-grain "$tmp/drift" --cells 2,2,3 --period 0.005 --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "coarse-grain exit status"
for f in field.csv field.vti rz.csv coarse_grain.json; do
  check "writes $f" "[ -s '$tmp/drift/coarse_grain/$f' ]"
done
/usr/bin/python3 - "$tmp/drift/coarse_grain" > "$tmp/py" 2>&1 <<'PY'
import csv, json, math, sys
d = sys.argv[1]
meta = json.load(open(f"{d}/coarse_grain.json"))
# Snapshots at 0, 2.5, 5, 7.5, 10 ms: three pairs one period (5 ms) apart.
assert meta["intervals"] == 3, meta["intervals"]
rows = list(csv.DictReader(open(f"{d}/field.csv")))
assert len(rows) == 12, len(rows)
# Every grain drifts at (0.02, -0.01, 0.1) m/s: each cell with mass moves at that velocity.
for r in rows:
    if float(r["mass_density"]) > 0:
        for k, v in (("vx", 0.02), ("vy", -0.01), ("vz", 0.1)):
            assert abs(float(r[k]) - v) < 1e-9, (k, r[k])
assert abs(meta["axis_velocity"][2] - 0.1) < 1e-9, meta["axis_velocity"]
PY
rc=$?; check_rc "drift velocity recovered"
# A box that holds the grains at every snapshot: the cells share out all of the grains'
# volume, so mean solid fraction x box volume = sum of 4/3 pi r^3.
"$talus" analyse coarse-grain "$tmp/drift" --cells 3,2,4 --period 0.005 --quiet \
  --box=-0.001,-0.001,-0.001,0.005,0.005,0.006 --out "$tmp/cg_box" > "$tmp/py" 2>&1
rc=$?; check_rc "coarse-grain with --box and --out"
/usr/bin/python3 - "$tmp/cg_box" > "$tmp/py" 2>&1 <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(f"{sys.argv[1]}/field.csv")))
assert len(rows) == 24, len(rows)
solid = sum(4 / 3 * math.pi * r**3 for r in [7e-4] * 5 + [6e-4] * 2 + [5e-4])
mean = sum(float(r["solid_fraction"]) for r in rows) / len(rows)
assert abs(mean * 0.006 * 0.006 * 0.007 - solid) < 1e-12 * solid, (mean, solid)
PY
rc=$?; check_rc "solid volume shared out exactly"
"$talus" analyse coarse-grain "$tmp/drift" --cells 2,2,3 --period 0.003 --quiet 2> "$tmp/err"
check "no pairs one period apart: exit 2" "[ $? -eq 2 ] && grep -q 'no two snapshots' '$tmp/err'"
"$talus" analyse coarse-grain "$tmp/drift" --cells 2,2 --period 0.005 --quiet 2> "$tmp/err"
check "two cell counts: exit 2" "[ $? -eq 2 ] && grep -q 'cells' '$tmp/err'"
"$talus" analyse coarse-grain "$tmp/nothing" --cells 2,2,2 --period 0.005 --quiet 2> "$tmp/err"
check "no run folder: exit 2" "[ $? -eq 2 ] && grep -q 'particles.pvd' '$tmp/err'"
finish coarse_grain
