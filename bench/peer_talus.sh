#!/usr/bin/env bash
# One talus run of the peer column with bench/peer.sh's settings, for A/B timing
# of two binaries in the same sitting (talus only, no LIGGGHTS).
# Usage: bench/peer_talus.sh BIN THREADS [STEPS]   (default 60000)
# Prints loop seconds, neighbour builds, final KE and front.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$1 th=$2 steps=${3:-60000}
nx=20 ny=10 nz=40
read -r lx ly lz Lx Lz t < <(awk -v nx="$nx" -v ny="$ny" -v nz="$nz" -v s="$steps" \
  'BEGIN{a=0.00201; printf "%.10g %.10g %.10g %.10g %.10g %.10g\n", nx*a, ny*a, nz*a, 6*nx*a, 1.5*nz*a, s*5e-6}')
out=${BENCH_DIR:-/tmp/talus_bench}/peer_talus_t$th
# The folder is this script's: binaries older than the .talus-run record would
# leave it unrecorded, and a newer --force refuses such a folder.
rm -rf "$out"
"$bin" run "$root/scenarios/dem/column_collapse.toml" --out "$out" --force --quiet --threads "$th" \
  --set "run.duration=$t" --set "run.domain={min=[0,0,0],max=[$Lx,$ly,$Lz]}" \
  --set "walls.3.point=[0,$ly,0]" --set "particles.0.box={min=[0,0,0],max=[$lx,$ly,$lz]}" \
  --set "output.snapshots=false" --set "output.checkpoint_interval=0" --set "output.series_interval=$t"
/usr/bin/python3 -c "import json,sys;d=json.load(open(sys.argv[1]));r=d['run'];m=d['metrics'];print('loop_s=%.3f builds=%s ke=%r front=%r'%(r['loop_wall_s'],r['neighbour_builds'],m['kinetic_energy_J'],m['front_x_m']))" "$out/summary.json"
