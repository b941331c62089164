#!/usr/bin/env bash
# Output folders are safe (issue 28 §3): a run name is a plain name, --force
# empties only a folder whose every entry talus wrote (recorded in .talus-run),
# a folder another run is writing in is refused, and each refusal leaves the
# folder as it was. Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
small=(--set "run.duration=0.002" --set "particles.0.box={min=[0,0,0],max=[0.01206,0.00804,0.02412]}"
       --set "output.snapshot_interval=0.001")
cc=$src/scenarios/dem/column_collapse.toml

"$talus" run "$cc" --out "$tmp/run" --quiet "${small[@]}" >"$tmp/out" 2>&1; rc=$?
check "run exits 0" '[ $rc -eq 0 ]'
check "the run folder records what talus wrote" 'head -1 "$tmp/run/.talus-run" | grep -q finished && grep -qx summary.json "$tmp/run/.talus-run"'

echo "mine" >"$tmp/run/notes.txt"
"$talus" run "$cc" --out "$tmp/run" --force --quiet "${small[@]}" >"$tmp/out" 2>&1; rc=$?
check "--force refuses a run folder holding a file talus did not write (exit 2)" '[ $rc -eq 2 ] && grep -q "notes.txt" "$tmp/out"'
check "the refused --force deleted nothing" '[ -s "$tmp/run/notes.txt" ] && [ -s "$tmp/run/summary.json" ]'
rm "$tmp/run/notes.txt"
"$talus" run "$cc" --out "$tmp/run" --force --quiet "${small[@]}" >"$tmp/out" 2>&1; rc=$?
check "--force empties a folder of talus's own files" '[ $rc -eq 0 ] && grep -q completed "$tmp/run/summary.json"'

mkdir -p "$tmp/mine" && echo "data" >"$tmp/mine/thesis.tex"
"$talus" run "$cc" --out "$tmp/mine" --force --quiet "${small[@]}" >"$tmp/out" 2>&1; rc=$?
check "--force refuses a folder talus never ran in (exit 2)" '[ $rc -eq 2 ] && grep -q "not a talus run folder" "$tmp/out"'
check "and leaves it untouched" '[ "$(ls -A "$tmp/mine")" = "thesis.tex" ]'

printf 'talus run folder: running\n' >"$tmp/run/.talus-run"
"$talus" run "$cc" --out "$tmp/run" --force --quiet "${small[@]}" >"$tmp/out" 2>&1; rc=$?
check "--force refuses the folder of a run that did not finish (exit 2)" '[ $rc -eq 2 ] && grep -q "did not finish" "$tmp/out"'
printf 'talus run folder: finished\n' >"$tmp/run/.talus-run"
ls -A "$tmp/run" | grep -v '^\.talus' >>"$tmp/run/.talus-run"

# Another process holds the folder's lock (as a running talus does).
flock "$tmp/run/.talus-lock" sleep 10 &
holder=$!
sleep 0.5
"$talus" run "$cc" --out "$tmp/run" --force --quiet "${small[@]}" >"$tmp/out" 2>&1; rc=$?
check "a folder another run is writing in is refused (exit 2)" '[ $rc -eq 2 ] && grep -q "another talus run" "$tmp/out"'
check "and left as it was" '[ -s "$tmp/run/summary.json" ]'
kill $holder 2>/dev/null; wait $holder 2>/dev/null

(cd "$tmp" && mkdir -p a/b && cd a/b && "$talus" run "$cc" --quiet "${small[@]}" --set 'name="../../escaped"') >"$tmp/out" 2>&1; rc=$?
check "a run name with a path is refused (exit 2), naming the key" '[ $rc -eq 2 ] && grep -q "plain name" "$tmp/out" && grep -q "escaped" "$tmp/out"'
check "and nothing was written outside" '[ ! -e "$tmp/escaped" ] && [ ! -e "$tmp/a/b/runs" ]'
"$talus" validate "$cc" --set 'name="/tmp/x"' >"$tmp/out" 2>&1; rc=$?
check "validate refuses an absolute run name (exit 2)" '[ $rc -eq 2 ] && grep -q "plain name" "$tmp/out"'

# A place no one can create a folder in (even root): below a plain file.
echo "x" >"$tmp/plain"
"$talus" run "$cc" --out "$tmp/plain/run" --quiet "${small[@]}" >"$tmp/out" 2>&1; rc=$?
check "an unwritable place is refused in plain words (exit 2)" '[ $rc -eq 2 ] && grep -q "cannot create the output folder" "$tmp/out" && ! grep -q "filesystem error" "$tmp/out"'

finish output_folder
