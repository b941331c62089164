#!/usr/bin/env bash
# DAN, fv2d and two-phase runs killed with SIGKILL after a checkpoint and
# resumed with --resume end as an uninterrupted run does (issue 28 §2): the
# series, the results (DAN: front.csv, deposit.csv, the last block snapshot;
# fv2d: the maxima and deposit rasters; two-phase: every map of each phase)
# are byte-identical, and so are summary.json's metrics (peaks, arrival,
# run-up, released volume). Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"

same() {  # name, file in both run folders
  local run=$1 file=$2
  check "$run: $file identical" \
    'cmp -s "$tmp/$run-full/$file" "$tmp/$run/$file" || { diff "$tmp/$run-full/$file" "$tmp/$run/$file" | head -4; false; }'
}

same_metrics() {  # name
  local run=$1
  /usr/bin/python3 - "$tmp/$run-full" "$tmp/$run" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import json, sys
a, b = (json.load(open(d + "/summary.json")) for d in sys.argv[1:3])
assert a["status"] == b["status"] == "completed", (a["status"], b["status"])
assert a["metrics"] == b["metrics"], (a["metrics"], b["metrics"])
assert a["run"]["simulated_time_s"] == b["run"]["simulated_time_s"]
PY
  check_rc "$run: summary metrics identical"
}

killed_and_resumed dan "$src/tests/data/scenarios/dan_resume.toml"
for f in series.csv front.csv deposit.csv path.csv blocks.pvd; do same dan $f; done
last=$(ls "$tmp/dan-full"/blocks_*.vtu | tail -1 | xargs basename)
same dan "$last"
same_metrics dan
/usr/bin/python3 - "$tmp/dan/summary.json" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import json, math, sys
m = json.load(open(sys.argv[1]))["metrics"]
# The checkpointed state carries what the run gathered before it: the front
# reached the barrier (arrival 0.31 s) and ran up it before the first
# checkpoint at 0.5 s (run-up peak at 1.4 s).
assert math.isfinite(m["barrier_arrival_time_s"]) and m["barrier_arrival_time_s"] < 0.5, m
assert m["runup_max"]["distance_on_barrier_m"] > 0.3, m
PY
check_rc "dan: arrival and run-up from before the checkpoint kept"

killed_and_resumed fv2d "$src/tests/data/scenarios/fv2d_resume.toml"
for f in series.csv max_height.npy max_speed.npy max_pressure.npy arrival_time.npy deposit.npy; do same fv2d $f; done
# Snapshot maps every 5 s: the list, the ParaView collection and the last maps.
for f in snapshots/times.csv snapshots/flow.pvd; do same fv2d $f; done
last=$(ls "$tmp/fv2d-full"/snapshots/height_*.tif | tail -1 | xargs basename)
check "fv2d: snapshots after the checkpoint ($last)" '[ "$last" != height_000001.tif ]'
same fv2d "snapshots/$last"
same fv2d "snapshots/${last/height/speed}"
same fv2d "snapshots/$(ls "$tmp/fv2d-full"/snapshots/flow_*.vtu | tail -1 | xargs basename)"
same_metrics fv2d

# On two threads (the resume takes the run's two from its folder).
killed_and_resumed fv2d_2 "$src/tests/data/scenarios/fv2d_resume.toml" 2
for f in series.csv max_height.npy deposit.npy; do same fv2d_2 $f; done
same_metrics fv2d_2

killed_and_resumed two_phase "$src/tests/data/scenarios/two_phase_resume.toml"
for f in series.csv max_height max_solid_height max_fluid_height max_solid_speed max_fluid_speed \
  max_pressure max_solid_pressure max_fluid_pressure arrival_time deposit deposit_solid \
  deposit_fluid solid_fraction; do
  [ "$f" = series.csv ] && same two_phase $f || same two_phase $f.npy
done
for f in snapshots/times.csv snapshots/flow.pvd; do same two_phase $f; done
last=$(ls "$tmp/two_phase-full"/snapshots/height_*.tif | tail -1 | xargs basename)
check "two_phase: snapshots after the checkpoint ($last)" '[ "$last" != height_000001.tif ]'
for field in height solid_fraction solid_speed fluid_speed; do
  same two_phase "snapshots/${last/height/$field}"
done
same_metrics two_phase

# A grid model on a flume path: the flume results gathered before the
# checkpoint (arrival at the barrier at 0.48 s) come through it.
killed_and_resumed two_phase_flume "$src/tests/data/scenarios/two_phase_flume_resume.toml"
for f in series.csv front.csv deposit.csv path.csv deposit.npy; do same two_phase_flume $f; done
same_metrics two_phase_flume

# A runout folder without a checkpoint: the usual refusal, naming the key.
mkdir -p "$tmp/none" && cp "$tmp/dan-full/scenario.toml" "$tmp/none/"
"$talus" run --resume "$tmp/none" >"$tmp/out" 2>&1; rc=$?
check "resume without checkpoint exits 2, naming checkpoint_interval" \
  '[ $rc -eq 2 ] && grep -q "checkpoint_interval" "$tmp/out" || { cat "$tmp/out"; false; }'
finish resume_runout
