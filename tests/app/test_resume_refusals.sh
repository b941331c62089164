#!/usr/bin/env bash
# --resume continues a run exactly as it was set up, or refuses with the reason
# (issue 28 §2): a completed run, extra options, an edited scenario.toml and a
# checkpoint.bin that is not a file are refused with exit 2 and leave the
# folder as it was. Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
args=(run "$src/scenarios/dem/column_collapse.toml" --quiet
      --set "run.duration=0.004" --set "particles.0.box={min=[0,0,0],max=[0.01206,0.00804,0.02412]}"
      --set "output.snapshot_interval=0.002" --set "output.checkpoint_interval=0.001")
"$talus" "${args[@]}" --out "$tmp/run" >"$tmp/out" 2>&1; rc=$?
check "the run exits 0 and writes a checkpoint" '[ $rc -eq 0 ] && [ -f "$tmp/run/checkpoint.bin" ]'
check "its record holds the scenario checksum" 'sed -n 2p "$tmp/run/.talus-run" | grep -Eq "^scenario [0-9a-f]{16}$"'

before=$(md5sum "$tmp/run/summary.json")
"$talus" run --resume "$tmp/run" >"$tmp/out" 2>&1; rc=$?
check "resuming a completed run is refused (exit 2)" '[ $rc -eq 2 ] && grep -q "completed" "$tmp/out"'
check "and its summary is left as it was" '[ "$(md5sum "$tmp/run/summary.json")" = "$before" ]'

# As if killed after its last checkpoint: no summary yet.
rm "$tmp/run/summary.json"
"$talus" run --resume "$tmp/run" --set run.duration=1 >"$tmp/out" 2>&1; rc=$?
check "--resume with --set is refused (exit 2)" '[ $rc -eq 2 ] && grep -q "cannot be honoured" "$tmp/out"'
"$talus" run --resume "$tmp/run" --out "$tmp/elsewhere" >"$tmp/out" 2>&1; rc=$?
check "--resume with --out is refused (exit 2)" '[ $rc -eq 2 ] && [ ! -e "$tmp/elsewhere" ]'

cp "$tmp/run/scenario.toml" "$tmp/scenario.keep"
sed -i 's/^duration = .*/duration = 0.5/' "$tmp/run/scenario.toml"
"$talus" run --resume "$tmp/run" >"$tmp/out" 2>&1; rc=$?
check "an edited scenario.toml is refused (exit 2)" '[ $rc -eq 2 ] && grep -q "was changed after the run started" "$tmp/out"'
cp "$tmp/scenario.keep" "$tmp/run/scenario.toml"
"$talus" run --resume "$tmp/run" --quiet >"$tmp/out" 2>&1; rc=$?
check "with the scenario restored the run resumes (exit 0)" '[ $rc -eq 0 ] && grep -q "\"completed\"" "$tmp/run/summary.json"'

mkdir -p "$tmp/dir_ck" && cp "$tmp/run/scenario.toml" "$tmp/dir_ck/" && mkdir "$tmp/dir_ck/checkpoint.bin"
"$talus" run --resume "$tmp/dir_ck" >"$tmp/out" 2>&1; rc=$?
check "a checkpoint.bin that is a folder is refused (exit 2)" '[ $rc -eq 2 ] && grep -q "not a file" "$tmp/out"'

finish resume_refusals
