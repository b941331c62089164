#!/usr/bin/env bash
# Every run writes log.txt (start, a progress line every --log-interval wall
# seconds, end), and a run whose stderr is not a terminal (a batch job) writes
# the same lines there (issue 28 §5). Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
# About 2 s of wall time or more: 20000 steps of 5e-6 s.
"$talus" run "$src/scenarios/column_collapse.toml" --out "$tmp/run" --log-interval 0.2 \
  --set "run.duration=0.1" --set "particles.0.box={min=[0,0,0],max=[0.0201,0.0201,0.0402]}" \
  --set "output.snapshots=false" 2>"$tmp/err"; rc=$?
check "the run exits 0" '[ $rc -eq 0 ]'
check "log.txt says what started" 'head -1 "$tmp/run/log.txt" | grep -q "started .*column_collapse.toml (dem, 1 thread)"'
check "log.txt has progress lines with time, rate and time left" 'grep -Eq "t = [0-9.e-]+ / 0.1 s, [0-9]+ steps/s, dt = 5e-06 s, about [0-9]+ s left" "$tmp/run/log.txt"'
check "log.txt says how the run ended" 'tail -1 "$tmp/run/log.txt" | grep -q "completed: 20000 steps to t = 0.1 s"'
check "stderr of a batch job carries the same lines" '[ "$(grep -c " t = " "$tmp/err")" = "$(grep -c " t = " "$tmp/run/log.txt")" ] && grep -q "completed: 20000 steps" "$tmp/err"'
"$talus" run "$src/scenarios/column_collapse.toml" --out "$tmp/quiet" --quiet \
  --set "run.duration=0.002" --set "particles.0.box={min=[0,0,0],max=[0.01206,0.00804,0.02412]}" 2>"$tmp/err"
check "--quiet keeps stderr empty but still writes log.txt" '[ ! -s "$tmp/err" ] && grep -q completed "$tmp/quiet/log.txt"'
finish run_log
