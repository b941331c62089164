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

printf 'extends = "%s"\n[run]\nduraton = 1\n' "$src/scenarios/collapse_2d.toml" >"$tmp/c.toml"
refused "a typo in a file that extends another" "c.toml:3: [run] 'duraton': unknown key" \
  "$tmp/c.toml"

sed 's/^duration = 1.0/duration = 1.0\ntime_step = 1e-5/' "$src/scenarios/collapse_2d.toml" \
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
sed 's/^time_step = .*/time_step = 0.01/' "$src/scenarios/mpm_column_collapse.toml" >"$tmp/mpm_step.toml"
line=$(grep -n '^time_step' "$tmp/mpm_step.toml" | cut -d: -f1)
refused "an MPM step above the stable one" \
  "mpm_step.toml:$line: [run] 'time_step': 0.01 s is above the stable step" "$tmp/mpm_step.toml"
check "... saying what would do" 'grep -q "use time_step = \"auto\"" "$tmp/out"'
"$talus" run "$tmp/mpm_step.toml" --out "$tmp/mpm_run" --quiet >"$tmp/out" 2>&1; rc=$?
check "talus run refuses it too (exit 2)" '[ $rc -eq 2 ] && grep -q "above the stable step" "$tmp/out"'

finish "input refusals"
