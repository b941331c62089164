#!/usr/bin/env bash
# fv2d and the two-phase model give the same bits on one thread, on two, and
# on two that run their segments all as a team or all alone (TALUS_TEAM,
# core/team_segments.hpp): their loops are per cell or a max, so how many
# threads take a step does not change a number (issue 28 §1: a busy machine
# may switch the team at any segment). Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
scenario=$src/scenarios/runout/runout_terrain_2d.toml
# With snapshot maps every 20 s (their own loop over the cells).
snap=output.snapshot_interval=20
"$talus" run "$scenario" --out "$tmp/one" --quiet -j 1 --set $snap >"$tmp/py" 2>&1; rc=$?
check_rc "one thread"
for mode in adaptive team alone; do
  TALUS_TEAM=$([ $mode = adaptive ] || echo $mode) \
    "$talus" run "$scenario" --out "$tmp/$mode" --quiet -j 2 --set $snap >"$tmp/py" 2>&1; rc=$?
  check_rc "two threads, $mode"
  for f in series.csv max_height.npy max_speed.npy max_pressure.npy arrival_time.npy deposit.npy \
    snapshots/times.csv snapshots/height_000003.tif snapshots/speed_000003.tif; do
    check "two threads, $mode: $f as on one thread" 'cmp -s "$tmp/one/$f" "$tmp/$mode/$f"'
  done
  # What the summary reports (the run ends by its momentum rule: peak momentum,
  # stop time, areas, maxima).
  check "two threads, $mode: summary metrics and end time as on one thread" \
    '/usr/bin/python3 -c "import json,sys; a,b=(json.load(open(d+\"/summary.json\")) for d in sys.argv[1:]); sys.exit(0 if a[\"metrics\"]==b[\"metrics\"] and a[\"run\"][\"simulated_time_s\"]==b[\"run\"][\"simulated_time_s\"] else 1)" "$tmp/one" "$tmp/$mode"'
done
# The two-phase model through the method: its per-phase maps and summary.
valley=$src/scenarios/runout/two_phase_debris_valley.toml
short=(--set run.duration=20 --set output.snapshot_interval=10)
"$talus" run "$valley" --out "$tmp/tp_one" --quiet -j 1 "${short[@]}" >"$tmp/py" 2>&1; rc=$?
check_rc "two-phase, one thread"
for mode in adaptive team alone; do
  TALUS_TEAM=$([ $mode = adaptive ] || echo $mode) \
    "$talus" run "$valley" --out "$tmp/tp_$mode" --quiet -j 2 "${short[@]}" >"$tmp/py" 2>&1; rc=$?
  check_rc "two-phase, two threads, $mode"
  for f in series.csv max_solid_height.npy max_fluid_speed.npy max_solid_pressure.npy \
    solid_fraction.npy deposit_solid.npy deposit_fluid.npy arrival_time.npy \
    snapshots/flow_000002.vtu; do
    check "two-phase, two threads, $mode: $f as on one thread" \
      'cmp -s "$tmp/tp_one/$f" "$tmp/tp_$mode/$f"'
  done
  check "two-phase, two threads, $mode: summary metrics as on one thread" \
    '/usr/bin/python3 -c "import json,sys; a,b=(json.load(open(d+\"/summary.json\")) for d in sys.argv[1:]); sys.exit(0 if a[\"metrics\"]==b[\"metrics\"] else 1)" "$tmp/tp_one" "$tmp/tp_$mode"'
done
finish runout_threads
