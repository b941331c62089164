#!/usr/bin/env bash
# Command-line contract: exit codes, error messages naming file/line/key,
# output folder protection, outputs of a run. Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
small=(--set "run.duration=0.002" --set "particles.0.box={min=[0,0,0],max=[0.01206,0.00804,0.02412]}"
       --set "output.snapshot_interval=0.001")
cc=$src/scenarios/dem/column_collapse.toml

"$talus" validate "$cc" >"$tmp/out" 2>&1; rc=$?
check "validate bundled scenario exits 0" '[ $rc -eq 0 ] && grep -q valid "$tmp/out"'

sed 's/^youngs_modulus = 1e7/youngs_modulus = 1e7\ndensty = 2500/' "$cc" >"$tmp/typo.toml"
"$talus" validate "$tmp/typo.toml" >"$tmp/out" 2>&1; rc=$?
line=$(grep -n '^densty' "$tmp/typo.toml" | cut -d: -f1)
check "unknown key exits 2" '[ $rc -eq 2 ]'
check "unknown key names file, line and key" 'grep -q "typo.toml:$line" "$tmp/out" && grep -q densty "$tmp/out"'

sed 's/^density = 2500/density = -2500/' "$cc" >"$tmp/neg.toml"
"$talus" validate "$tmp/neg.toml" >"$tmp/out" 2>&1; rc=$?
check "negative density exits 2 naming the key" '[ $rc -eq 2 ] && grep -q density "$tmp/out"'

"$talus" validate "$cc" --set run.time_step=1e-3 >"$tmp/out" 2>&1; rc=$?
check "time step above critical exits 2" '[ $rc -eq 2 ] && grep -q "critical" "$tmp/out"'

"$talus" validate "$cc" --set "run.domain={min=[0,0,0],max=[0.01,0.0201,0.1206]}" >"$tmp/out" 2>&1; rc=$?
check "particles outside the domain exit 2" '[ $rc -eq 2 ] && grep -q "outside the domain" "$tmp/out"'

"$talus" run "$tmp/missing.toml" --out "$tmp/x" >"$tmp/out" 2>&1; rc=$?
check "missing file exits 2" '[ $rc -eq 2 ]'

"$talus" run "$cc" --out "$tmp/run" --quiet "${small[@]}" >"$tmp/out" 2>&1; rc=$?
check "small run exits 0" '[ $rc -eq 0 ]'
for f in summary.json series.csv particles.pvd walls.pvd scenario.toml particles_000000.vtu; do
  check "run writes $f" '[ -s "$tmp/run/$f" ]'
done
check "summary has status and metrics" 'grep -q "\"status\": \"completed\"" "$tmp/run/summary.json" && grep -q kinetic_energy_J "$tmp/run/summary.json"'
check "series has a header and rows" '[ $(wc -l <"$tmp/run/series.csv") -ge 3 ] && head -1 "$tmp/run/series.csv" | grep -q "^time,step"'

before=$(stat -c %Y "$tmp/run/summary.json")
"$talus" run "$cc" --out "$tmp/run" --quiet "${small[@]}" >"$tmp/out" 2>&1; rc=$?
check "existing output folder is refused (exit 2)" '[ $rc -eq 2 ] && grep -q -- "--force" "$tmp/out"'
check "refused run left the folder alone" '[ "$(stat -c %Y "$tmp/run/summary.json")" = "$before" ]'
"$talus" run "$cc" --out "$tmp/run" --force --quiet "${small[@]}" >"$tmp/out" 2>&1; rc=$?
check "--force overwrites" '[ $rc -eq 0 ]'

"$talus" list >"$tmp/out" 2>&1; rc=$?
check "list shows bundled scenarios" '[ $rc -eq 0 ] && grep -q column_collapse "$tmp/out"'

# Every bundled scenario validates as it is, by the name `talus list` shows.
"$talus" list >"$tmp/list" 2>&1
check "list shows every bundled file with its method" '[ "$(wc -l <"$tmp/list")" -eq "$(find "$src"/scenarios -name "*.toml" | wc -l)" ] && grep -Eq "^column_collapse +dem 3D +0.3 s" "$tmp/list"'
# The files sit in sub-folders (dem/, mpm/, runout/, compare/); a name is the
# file's stem, so two files may not share one.
check "list names are unique across the sub-folders" '[ -z "$(awk "{print \$1}" "$tmp/list" | sort | uniq -d)" ]'
check "list shows a scenario of each sub-folder" 'grep -q "^flume_A_model3 " "$tmp/list" && grep -q "^mpm_flume_A " "$tmp/list" && grep -q "^two_phase_debris_valley " "$tmp/list" && grep -q "^compare_flume_A " "$tmp/list"'
for name in $(awk '{print $1}' "$tmp/list"); do
  "$talus" validate "$name" >"$tmp/out" 2>&1; rc=$?
  check "bundled $name validates by name" '[ $rc -eq 0 ]'
done
mkdir -p "$tmp/clash/a" "$tmp/clash/b"
cp "$cc" "$tmp/clash/a/same.toml"; cp "$cc" "$tmp/clash/b/same.toml"
TALUS_SCENARIOS=$tmp/clash "$talus" validate same >"$tmp/out" 2>&1; rc=$?
check "a name two sub-folders share is refused (exit 2)" '[ $rc -eq 2 ] && grep -q "give the file" "$tmp/out"'
"$talus" validate no_such_scenario >"$tmp/out" 2>&1; rc=$?
check "an unknown name is refused (exit 2)" '[ $rc -eq 2 ] && grep -q "talus list" "$tmp/out"'

finish cli
