#!/usr/bin/env bash
# Runs with membranes resume bit for bit (dem/checkpoint.cpp, version 4): a
# run killed with SIGKILL after a checkpoint and resumed with --resume ends
# with the same bytes as an uninterrupted run. Two cases: grains dropped onto
# a pinned sheet (grain-membrane friction springs; self-contact on, so its
# springs and series column go through the checkpoint too), and a small
# triaxial test (servo plates, rings that follow them, confining pressure,
# triaxial.csv and the summary's triaxial numbers).
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"

# name, files to compare, then the run's arguments.
resume_case() {
  local name=$1 files=$2; shift 2
  local args=("$@")
  "$talus" "${args[@]}" --out "$tmp/$name-full" || { echo "FAIL: $name: uninterrupted run"; fail=$((fail+1)); return; }
  "$talus" "${args[@]}" --out "$tmp/$name-killed" & local pid=$!
  wait_for_checkpoint "$tmp/$name-killed" $pid
  if ! kill -0 $pid 2>/dev/null; then
    echo "FAIL: $name: the run finished before it could be killed; make it longer"
    fail=$((fail+1)); return
  fi
  kill -9 $pid; wait $pid 2>/dev/null
  check "$name: checkpoint written" '[ -f "$tmp/$name-killed/checkpoint.bin" ]'
  check "$name: killed run incomplete" '[ ! -f "$tmp/$name-killed/summary.json" ]'
  "$talus" run --resume "$tmp/$name-killed" --quiet
  check "$name: resume" '[ $? -eq 0 ]'
  local last
  last=$(ls "$tmp/$name-full"/particles_*.vtu | tail -1 | xargs basename)
  for f in $files "$last"; do
    check "$name: $f identical" 'cmp -s "$tmp/$name-full/$f" "$tmp/$name-killed/$f" || { diff "$tmp/$name-full/$f" "$tmp/$name-killed/$f" | head -5; false; }'
  done
  # Every physics figure of the summary (peaks included), not only the files.
  check "$name: summary metrics identical" 'python3 - "$tmp/$name-full/summary.json" "$tmp/$name-killed/summary.json" <<PY
import json, sys
a, b = (json.load(open(p))["metrics"] for p in sys.argv[1:])
if a != b:
    print({k: (a[k], b.get(k)) for k in a if a[k] != b.get(k)})
sys.exit(0 if a == b and a["peak_kinetic_energy_J"] > 0 else 1)
PY'
}

# The sheet drop with 158 grains released just above the sheet, so that they
# are on it (13 contacts with friction springs at the first checkpoint,
# t = 0.02 s). About 7 s of wall time.
sheet=(run "$src/scenarios/dem/membrane_sheet_drop.toml" --quiet
       --set "run.duration=0.15" --set "membranes.0.self_contact=true"
       --set "particles.0.box={min=[0.03,0.03,0.0001],max=[0.07,0.07,0.012]}"
       --set "output.snapshot_interval=0.05" --set "output.series_interval=0.001"
       --set "output.checkpoint_interval=0.02")
resume_case sheet "series.csv particles.pvd membrane_sheet.pvd" "${sheet[@]}"
last_membrane=$(ls "$tmp/sheet-full"/membrane_sheet_*.vt* | tail -1 | xargs basename)
check "sheet: $last_membrane identical" 'cmp -s "$tmp/sheet-full/$last_membrane" "$tmp/sheet-killed/$last_membrane"'
check "sheet: self_contacts column" 'head -1 "$tmp/sheet-full/series.csv" | grep -q sheet_self_contacts'

# Triaxial case 1 scaled down: R 12.5 mm, H 30 mm, 100 grains; servo until
# 2 ms, then loading to 8 ms; checkpoints in both phases. About 3 s.
area=4.908738521234052e-4  # pi R^2
servo="{pressure=1e5,area=$area,speed=0.05,stop=0.002}"
tri=(run "$src/scenarios/dem/triaxial_case1.toml" --quiet
     --set "run.duration=0.008" --set "run.domain={min=[-0.03,-0.03,-0.01],max=[0.03,0.03,0.04]}"
     --set "walls.0.motion.servo=$servo" --set "walls.0.motion.start=0.002"
     --set "walls.1.motion.servo=$servo" --set "walls.1.motion.start=0.002"
     --set "walls.1.point=[0,0,0.03]"
     --set "particles.0.cylinder={center=[0,0,0],radius=0.0124,height=0.03}"
     --set "particles.0.count=100"
     --set "membranes.0.radius=0.0125" --set "membranes.0.height=0.03"
     --set "output.snapshot_interval=0.002" --set "output.series_interval=0.0001"
     --set "output.checkpoint_interval=0.0005")
resume_case triaxial "series.csv triaxial.csv particles.pvd membrane_sleeve.pvd" "${tri[@]}"
check "triaxial: summary numbers identical" 'python3 - "$tmp/triaxial-full/summary.json" "$tmp/triaxial-killed/summary.json" <<PY
import json, sys
a, b = (json.load(open(p))["triaxial"] for p in sys.argv[1:])
sys.exit(0 if a == b and "h0" in a else 1)
PY'

finish resume_membrane
