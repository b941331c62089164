#!/usr/bin/env bash
# --backend gpu / run.backend = "gpu" (issue 35): a scenario using what the GPU
# backend lacks is refused with the list, a machine without a usable GPU (or a
# build without nvcc) says so, both with exit 2 before anything is written.
# On a machine with a GPU the run goes ahead (bench/gpu_check.sh covers it).
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"

refused() {  # name, expected fragment, command arguments...
  local name=$1 fragment=$2; shift 2
  timeout 60 "$talus" "$@" >"$tmp/out" 2>&1; rc=$?
  check "$name exits 2" '[ $rc -eq 2 ] || { cat "$tmp/out"; false; }'
  check "$name says: $fragment" 'grep -qF -- "$fragment" "$tmp/out" || { cat "$tmp/out"; false; }'
}

# Kuen's rolling resistance is not on the GPU: the list names it, whatever the machine.
refused "Kuen rolling on the GPU" 'rolling = "kuen"' \
  validate "$src/scenarios/dem/flume_A_model3.toml" --backend gpu
check "... and says how to run it" 'grep -qF "run it with --backend cpu" "$tmp/out"'
refused "membranes on the GPU" "[[membranes]]" \
  validate "$src/scenarios/dem/granular_gripper_small.toml" --backend gpu
check "... with the experiment" 'grep -qF "the [gripper] experiment" "$tmp/out"'
refused "run.backend in the file" "[[membranes]]" \
  validate "$src/scenarios/dem/granular_gripper_small.toml" --set 'run.backend="gpu"'
refused "an unknown backend" 'run.backend: expected one of "cpu" or "gpu"' \
  validate "$src/scenarios/dem/column_collapse.toml" --set 'run.backend="tpu"'

# The peer column has nothing the backend lacks: without a GPU it is refused
# for that reason alone, and `talus run` writes nothing.
timeout 60 "$talus" validate "$src/scenarios/dem/column_collapse.toml" --backend gpu >"$tmp/out" 2>&1
rc=$?
if [ $rc -eq 0 ]; then
  check "a GPU is here: the peer column validates" 'true'
else
  check "no GPU: exit 2" '[ $rc -eq 2 ] || { cat "$tmp/out"; false; }'
  check "no GPU: says why" \
    'grep -qE "no usable CUDA GPU|built without the CUDA backend" "$tmp/out" || { cat "$tmp/out"; false; }'
  timeout 60 "$talus" run "$src/scenarios/dem/column_collapse.toml" --backend gpu --out "$tmp/run" \
    --quiet >"$tmp/out" 2>&1
  rc=$?
  check "no GPU: run exits 2" '[ $rc -eq 2 ] || { cat "$tmp/out"; false; }'
  check "no GPU: no run folder" '[ ! -e "$tmp/run" ]'
fi
finish "GPU backend refusals"
