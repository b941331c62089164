# Sourced by tests/app/test_*.sh (not a test itself; the glob in
# tests/CMakeLists.txt only takes test_*.sh). Sets talus and src from the
# script's arguments <talus binary> <source dir>, a temporary folder $tmp
# removed on exit, and counts the checks.
set -uo pipefail
talus=$1 src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0; pass=0
check() {  # name, condition (command)
  if eval "$2"; then pass=$((pass+1)); else echo "FAIL: $1"; fail=$((fail+1)); fi
}
# For a command whose exit status is in $rc (a python heredoc, a run): passes
# when it is 0, otherwise shows its output (file, $tmp/py unless given).
check_rc() {  # name [output file]
  local output=${2:-$tmp/py}
  check "$1" '[ $rc -eq 0 ] || { cat "$output"; false; }'
}
# Waits until a run started in the background writes its first checkpoint (or
# ends), then a little longer so that it is inside its next stretch. No fixed
# count of polls: under a sanitizer on a loaded host the first checkpoint
# came after more than the 10 s such a loop used to allow.
wait_for_checkpoint() {  # output folder, pid of the run
  local deadline=$((SECONDS + 900))
  while [ ! -f "$1/checkpoint.bin" ] && kill -0 "$2" 2>/dev/null && [ $SECONDS -lt $deadline ]; do
    sleep 0.01
  done
  sleep 0.2
}
# Runs a scenario to its end into $tmp/NAME-full, and again into $tmp/NAME,
# killed with SIGKILL after its first checkpoint and resumed (a check each).
killed_and_resumed() {  # name, scenario[, threads (default 1)]
  local name=$1 scenario=$2 threads=${3:-1}
  "$talus" run "$scenario" --quiet -j "$threads" --out "$tmp/$name-full" >"$tmp/out" 2>&1; rc=$?
  check_rc "$name: uninterrupted run" "$tmp/out"
  "$talus" run "$scenario" --quiet -j "$threads" --out "$tmp/$name" & pid=$!
  wait_for_checkpoint "$tmp/$name" $pid
  check "$name: still going when killed (else make it longer)" 'kill -0 $pid 2>/dev/null'
  kill -9 $pid; wait $pid 2>/dev/null
  check "$name: a checkpoint was written" '[ -f "$tmp/$name/checkpoint.bin" ]'
  check "$name: the killed run had not finished" '[ ! -f "$tmp/$name/summary.json" ]'
  # Without -j: a resume runs on the thread count the run ran on.
  "$talus" run --resume "$tmp/$name" --quiet >"$tmp/out" 2>&1; rc=$?
  check_rc "$name: resume exits 0" "$tmp/out"
}

# Last line of a script: the tally, and its exit status.
finish() {  # name of the script's part
  echo "$1: $pass passed, $fail failed"
  [ $fail -eq 0 ]
}
# A tiny DEM scenario of listed grains, for the analyse tests: 10 ms, snapshots
# every 2.5 ms (five), one soft "grain" material (Hertz, E = 1e8 Pa). The grains
# come on stdin, one "{ position = ..., radius = ... }," entry a line.
dem_list_scenario() {  # name, dimension, gravity (a TOML array)
  cat <<TOML
method = "dem"
name = "$1"
[run]
dimension = $2
duration = 0.01
gravity = $3
[contact]
model = "viscoelastic_hertz"
[[materials]]
name = "grain"
density = 2000
youngs_modulus = 1e8
poisson_ratio = 0.245
friction = 0.5
dissipation = 7e-9
[[particles]]
type = "list"
material = "grain"
list = [
TOML
  cat
  printf ']\n[output]\nsnapshot_interval = 0.0025\n'
}
# Runs a scenario into a folder, quietly, as one check on its exit status.
run_check() {  # name of the check, scenario file, output folder
  "$talus" run "$2" --out "$3" --quiet > "$tmp/py" 2>&1
  rc=$?; check_rc "$1"
}
