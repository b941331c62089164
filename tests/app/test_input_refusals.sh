#!/usr/bin/env bash
# Input that used to hang, exhaust memory or pass silently (issue 28, section
# 4) is refused by `talus validate` at once with exit code 2, naming the file
# (and line). Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"

refused() {  # name, expected fragment, validate arguments...
  local name=$1 fragment=$2; shift 2
  timeout 20 "$talus" validate "$@" >"$tmp/out" 2>&1; rc=$?
  check "$name exits 2" '[ $rc -eq 2 ] || { cat "$tmp/out"; false; }'
  check "$name says: $fragment" 'grep -qF -- "$fragment" "$tmp/out" || { cat "$tmp/out"; false; }'
}

refused "/dev/zero as the scenario" "/dev/zero: is not a regular file" /dev/zero
refused "a folder as the scenario" "$tmp: is a folder" "$tmp"
printf 'extends = "/dev/urandom"\n' >"$tmp/urandom.toml"
refused "extends = /dev/urandom" "urandom.toml:1: 'extends': base scenario /dev/urandom" \
  "$tmp/urandom.toml"
printf 'extends = "."\n' >"$tmp/dot.toml"
refused "extends = ." "dot.toml:1: 'extends': base scenario" "$tmp/dot.toml"

printf 'extends = "%s"\n[run]\nduraton = 1\n' "$src/scenarios/dem/collapse_2d.toml" >"$tmp/c.toml"
refused "a typo in a file that extends another" "c.toml:3: [run] 'duraton': unknown key" \
  "$tmp/c.toml"

sed 's/^duration = 1.0/duration = 1.0\ntime_step = 1e-5/' "$src/scenarios/dem/collapse_2d.toml" \
  >"$tmp/step.toml"
line=$(grep -n '^time_step' "$tmp/step.toml" | cut -d: -f1)
timeout 60 "$talus" validate "$tmp/step.toml" >"$tmp/out" 2>&1; rc=$?
check "the step as written is valid" '[ $rc -eq 0 ] || { cat "$tmp/out"; false; }'
refused "a step above the critical one after --set" \
  "step.toml:$line: [run] 'time_step': 1e-05 s is above the critical time step" \
  "$tmp/step.toml" --set materials.0.density=2
check "... naming the density behind it" 'grep -qF "materials.0.density = 2 kg/m^3" "$tmp/out"'

# MPM: a fixed step above the stability limit blew up a few steps in and was
# reported as a point leaving the grid (issue 28 §4, §5).
sed 's/^time_step = .*/time_step = 0.01/' "$src/scenarios/mpm/mpm_column_collapse.toml" >"$tmp/mpm_step.toml"
line=$(grep -n '^time_step' "$tmp/mpm_step.toml" | cut -d: -f1)
refused "an MPM step above the stable one" \
  "mpm_step.toml:$line: [run] 'time_step': 0.01 s is above the stable step" "$tmp/mpm_step.toml"
check "... saying what would do" 'grep -q "use time_step = \"auto\"" "$tmp/out"'
"$talus" run "$tmp/mpm_step.toml" --out "$tmp/mpm_run" --quiet >"$tmp/out" 2>&1; rc=$?
check "talus run refuses it too (exit 2)" '[ $rc -eq 2 ] && grep -q "above the stable step" "$tmp/out"'
check "... and leaves no run folder behind" '[ ! -e "$tmp/mpm_run" ]'

# Runs that would never finish (issue 28 §4): a density of 1e-300 makes the
# MPM step 3e-156 s; a duration of 1e5 s makes 9e9 DEM steps.
refused "MPM density 1e-300" "about 3.12e+155 steps" "$src/scenarios/mpm/mpm_column_collapse.toml" \
  --set materials.0.density=1e-300
check "... and names the override" 'grep -q -- "--allow-long-run" "$tmp/out"'
timeout 20 "$talus" validate "$src/scenarios/mpm/mpm_column_collapse.toml" \
  --set materials.0.density=1e-300 --allow-long-run >"$tmp/out" 2>&1; rc=$?
check "--allow-long-run lets it pass validate" '[ $rc -eq 0 ] && grep -q "about 3.116e+155 steps" "$tmp/out"'
"$talus" run "$src/scenarios/dem/collapse_2d.toml" --set run.duration=1e5 --out "$tmp/long" \
  --quiet >"$tmp/out" 2>&1; rc=$?
check "a 9e9-step DEM run is refused by talus run (exit 2)" '[ $rc -eq 2 ] && grep -q "about 9.06e+09 steps" "$tmp/out"'
check "... leaving no run folder behind" '[ ! -e "$tmp/long" ]'

# A packing that cannot reach the porosity asked for is an input error.
refused "porosity 0.01 in a random fill" "[[particles]] #0: packing: porosity 0.0100 is not reachable" \
  "$src/scenarios/dem/collapse_2d.toml" --set particles.0.porosity=0.01

# A fixed DAN step above the stable one at the start (3.9 ms here) is refused.
refused "DAN time_step 1 s" "[run] 'time_step': 1 s is above the stable step 0.00386 s" \
  "$src/scenarios/runout/runout_flume_A.toml" --set run.time_step=1

# Sizes that would exhaust memory are refused with the estimate, before anything
# is allocated (they ended in std::bad_alloc).
refused "MPM cell_size 1e-9" "[grid] cell_size = 1e-09 m: 9.1e+17 grid nodes" \
  "$src/scenarios/mpm/mpm_column_collapse.toml" --set grid.cell_size=1e-9
check "... with the memory it would need" 'grep -q "GiB of memory, more than the" "$tmp/out"'
refused "membrane spacing 1e-6" "[[membranes]] 'sheet' at spacing = 1e-06 m: 1.15e+10 vertices" \
  "$src/scenarios/dem/membrane_sheet_drop.toml" --set membranes.0.spacing=1e-6
refused "a random fill of 1e8 particles" "[[particles]] #0: about 1e+08 particles would need about" \
  "$src/scenarios/dem/collapse_2d.toml" --set particles.0.count=100000000
TALUS_MEMORY_LIMIT=0.001 timeout 20 "$talus" validate "$src/scenarios/mpm/mpm_column_collapse.toml" \
  >"$tmp/out" 2>&1; rc=$?
check "a limit the user sets (TALUS_MEMORY_LIMIT) is kept" '[ $rc -eq 2 ] && grep -q "of TALUS_MEMORY_LIMIT" "$tmp/out"'

finish "input refusals"
