#!/usr/bin/env bash
# `mpirun -n N talus run` of an fv2d scenario (docs/mpi.md): the run folder
# holds the same files as a one-rank run, byte for byte (series, maps,
# rasters, snapshots, checkpoint, scenario.toml) and summary.json the same
# metrics; only rank 0 writes, and the log says how many ranks ran. A run on
# two ranks killed after a checkpoint resumes on one rank, and on two, to the
# same files. Everything else under mpirun is refused with exit status 2 (once,
# by rank 0): another method, a finished run's --resume, another command. Args: <talus binary> <source dir>.
source "$(dirname "$0")/../app/check_lib.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
# Under the sanitizers: OpenMPI's leaks named by tests/lsan.supp (see tests/CMakeLists.txt).
export OMPI_MCA_mca_base_component_disable_dlclose=1
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}fast_unwind_on_malloc=0"
mpi() { mpirun -n "$1" --oversubscribe "${@:2}"; }
scenario=$src/tests/data/scenarios/fv2d_resume.toml

same_run() {  # one-rank folder, other folder
  diff -r -q -x log.txt -x summary.json -x .talus-run -x .talus-lock "$1" "$2" >"$tmp/diff" &&
    /usr/bin/python3 - "$1/summary.json" "$2/summary.json" >>"$tmp/diff" 2>&1 <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
assert a["status"] == b["status"] == "completed", (a["status"], b["status"])
assert a["metrics"] == b["metrics"], (a["metrics"], b["metrics"])
PY
}

"$talus" run "$scenario" --quiet --out "$tmp/one" >"$tmp/out" 2>&1; rc=$?
check_rc "one rank runs" "$tmp/out"
for n in 2 4; do
  mpi $n "$talus" run "$scenario" --quiet --out "$tmp/n$n" >"$tmp/out" 2>&1; rc=$?
  check_rc "$n ranks run" "$tmp/out"
  check "$n ranks: the same files and metrics as one" 'same_run "$tmp/one" "$tmp/n$n" || { cat "$tmp/diff"; false; }'
  check "$n ranks: snapshots and a checkpoint written" '[ -f "$tmp/n$n/snapshots/flow.pvd" ] && [ -f "$tmp/n$n/checkpoint.bin" ]'
  check "$n ranks: the log says so" 'grep -q "each of $n MPI ranks" "$tmp/n$n/log.txt"'
  check "$n ranks: summary.json says so" \
    '/usr/bin/python3 -c "import json,sys; assert json.load(open(sys.argv[1]))[\"run\"][\"mpi_ranks\"] == $n" "$tmp/n$n/summary.json"'
done

# Killed on two ranks after a checkpoint, resumed on one.
mpi 2 "$talus" run "$scenario" --quiet --out "$tmp/killed" >/dev/null 2>&1 & pid=$!
wait_for_checkpoint "$tmp/killed" $pid
check "two ranks: still going when killed" 'kill -0 $pid 2>/dev/null'
kill -9 $pid; wait $pid 2>/dev/null
pkill -9 -f "talus run $scenario --quiet --out $tmp/killed" 2>/dev/null
sleep 0.2
cp -r "$tmp/killed" "$tmp/killed2"
"$talus" run --resume "$tmp/killed" --quiet >"$tmp/out" 2>&1; rc=$?
check_rc "resumed on one rank" "$tmp/out"
check "resumed on one rank: the same files and metrics" 'same_run "$tmp/one" "$tmp/killed" || { cat "$tmp/diff"; false; }'
mpi 2 "$talus" run --resume "$tmp/killed2" --quiet >"$tmp/out" 2>&1; rc=$?
check_rc "resumed on two ranks" "$tmp/out"
check "resumed on two ranks: the same files and metrics" 'same_run "$tmp/one" "$tmp/killed2" || { cat "$tmp/diff"; false; }'
check "resumed on two ranks: the log says so" 'grep -q "resumed.*each of 2 MPI ranks" "$tmp/killed2/log.txt"'

mpi 2 "$talus" run "$src/scenarios/dem/collapse_2d.toml" --out "$tmp/dem" >"$tmp/out" 2>&1; rc=$?
check "DEM on two ranks refused (exit 2, names fv2d), nothing written" \
  '[ $rc -eq 2 ] && grep -q "only fv2d runs on" "$tmp/out" && [ ! -e "$tmp/dem" ]'
check "the refusal printed once" '[ $(grep -c "only fv2d runs on" "$tmp/out") -eq 1 ]'
mpi 2 "$talus" run --resume "$tmp/one" >"$tmp/out" 2>&1; rc=$?
check "--resume of a finished run on two ranks refused once" \
  '[ $rc -eq 2 ] && [ $(grep -c "nothing to resume" "$tmp/out") -eq 1 ]'
mpi 2 "$talus" validate "$scenario" >"$tmp/out" 2>&1; rc=$?
check "validate on two ranks refused" '[ $rc -eq 2 ] && grep -q "started on 2 MPI ranks" "$tmp/out"'
mkdir -p "$tmp/taken" && touch "$tmp/taken/mine"
mpi 2 "$talus" run "$scenario" --quiet --out "$tmp/taken" >"$tmp/out" 2>&1; rc=$?
check "an error on rank 0 alone ends every rank (no hang), exit 2" \
  '[ $rc -eq 2 ] && grep -q "not empty" "$tmp/out"'
finish mpi_run
