#!/usr/bin/env bash
# fv2d gives the same bits on one thread, on two, and on two that run its
# segments all as a team or all alone (TALUS_TEAM, core/team_segments.hpp):
# its loops are per cell or a max, so how many threads take a step does not
# change a number (issue 28 §1: a busy machine may switch the team at any
# segment). Args: <talus binary> <source dir>.
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
finish runout_threads
