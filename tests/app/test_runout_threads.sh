#!/usr/bin/env bash
# fv2d gives the same bits on one thread, on two, and on two that run its
# segments all as a team or all alone (TALUS_TEAM, core/team_segments.hpp):
# its loops are per cell or a max, so how many threads take a step does not
# change a number (issue 28 §1: a busy machine may switch the team at any
# segment). Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
scenario=$src/scenarios/runout_terrain_2d.toml
"$talus" run "$scenario" --out "$tmp/one" --quiet -j 1 >"$tmp/py" 2>&1; rc=$?
check_rc "one thread"
for mode in adaptive team alone; do
  TALUS_TEAM=$([ $mode = adaptive ] || echo $mode) \
    "$talus" run "$scenario" --out "$tmp/$mode" --quiet -j 2 >"$tmp/py" 2>&1; rc=$?
  check_rc "two threads, $mode"
  for f in series.csv max_height.npy max_speed.npy max_pressure.npy arrival_time.npy deposit.npy; do
    check "two threads, $mode: $f as on one thread" 'cmp -s "$tmp/one/$f" "$tmp/$mode/$f"'
  done
done
finish runout_threads
