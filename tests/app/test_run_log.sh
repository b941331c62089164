#!/usr/bin/env bash
# Every run writes log.txt (start, a progress line every --log-interval wall
# seconds, end, the headline of its key results), and a run whose stderr is
# not a terminal (a batch job) writes the same lines there (issue 28 §5).
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
# About 2 s of wall time or more: 20000 steps of 5e-6 s.
"$talus" run "$src/scenarios/dem/column_collapse.toml" --out "$tmp/run" --log-interval 0.2 \
  --set "run.duration=0.1" --set "particles.0.box={min=[0,0,0],max=[0.0201,0.0201,0.0402]}" \
  --set "output.snapshots=false" 2>"$tmp/err"; rc=$?
check "the run exits 0" '[ $rc -eq 0 ]'
check "log.txt says what started and how many steps it takes" 'head -1 "$tmp/run/log.txt" | grep -q "started .*column_collapse.toml (dem, 1 thread, about 20000 steps)"'
check "summary.json keeps the estimate (run.estimated_steps)" 'python3 -c "import json,sys; r=json.load(open(sys.argv[1]))[\"run\"]; sys.exit(0 if abs(r[\"estimated_steps\"] - r[\"steps\"]) < 1 else 1)" "$tmp/run/summary.json"'
check "log.txt estimates the wall time at the first progress line" 'grep -Eq "estimated wall time: about [0-9]+ s \([0-9]+ s left at [0-9]+ steps/s\)" "$tmp/run/log.txt"'
# Within a factor 3 of the loop's wall time: the rate of the first 0.2 s on a
# shared machine, not a prediction to the second.
check "summary.json keeps it (run.estimated_wall_s)" 'python3 -c "import json,sys; r=json.load(open(sys.argv[1]))[\"run\"]; sys.exit(0 if r[\"loop_wall_s\"] / 3 < r[\"estimated_wall_s\"] < 3 * r[\"loop_wall_s\"] else 1)" "$tmp/run/summary.json"'
check "log.txt has progress lines with time, rate, time left and energy" 'grep -Eq "t = [0-9.e-]+ / 0.1 s, [0-9]+ steps/s, dt = 5e-06 s, about [0-9]+ s left, kinetic energy [0-9.e+-]+ J" "$tmp/run/log.txt"'
check "log.txt says how the run ended" 'tail -2 "$tmp/run/log.txt" | head -1 | grep -q "completed: 20000 steps to t = 0.1 s"'
check "and ends with the headline" 'tail -1 "$tmp/run/log.txt" | grep -Eq "dem: [0-9]+ particles, front at x = .* m; peak kinetic energy .* J at t = .* s; largest wall force .* N on"'
check "which stderr carries once" '[ "$(grep -c "dem: [0-9]* particles" "$tmp/err")" = 1 ]'
check "stderr of a batch job carries the same lines" '[ "$(grep -c " t = " "$tmp/err")" = "$(grep -c " t = " "$tmp/run/log.txt")" ] && grep -q "completed: 20000 steps" "$tmp/err"'
"$talus" run "$src/scenarios/dem/column_collapse.toml" --out "$tmp/quiet" --quiet \
  --set "run.duration=0.002" --set "particles.0.box={min=[0,0,0],max=[0.01206,0.00804,0.02412]}" 2>"$tmp/err"
check "--quiet keeps stderr empty but still writes log.txt" '[ ! -s "$tmp/err" ] && grep -q completed "$tmp/quiet/log.txt"'
# Every method ends with its headline (DAN, fv2d, MPM; the flume adds its own).
"$talus" run "$src/scenarios/runout/runout_flume_A.toml" --out "$tmp/dan" --quiet --set run.duration=0.5
check "a DAN run's headline: front, speed, depth" 'tail -2 "$tmp/dan/log.txt" | grep -Eq "dan: front at s = .* m; max speed .* m/s, max depth .* m"'
check "... and, cut short, the warning that it still moves" 'tail -1 "$tmp/dan/log.txt" | grep -q "warning: the mass is still moving at the end"'
"$talus" run "$src/scenarios/runout/runout_terrain_2d.toml" --out "$tmp/fv2d" --quiet --set run.duration=2
check "an fv2d run's headline: volume, areas, maxima" 'tail -2 "$tmp/fv2d/log.txt" | grep -Eq "fv2d: .* m\^3 released, .* m\^2 affected, .* deposit .*; max height .* m, max speed .* m/s, max pressure .* kPa"'
"$talus" run "$src/scenarios/mpm/mpm_tilting_plate.toml" --out "$tmp/mpm" --quiet --set run.duration=0.05
check "an MPM run's headline: front, top, energy" 'tail -1 "$tmp/mpm/log.txt" | grep -Eq "mpm: 200 points, front advanced .* m, top changed .* m; peak kinetic energy .* J at t = .* s"'
finish run_log
