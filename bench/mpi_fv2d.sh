#!/usr/bin/env bash
# fv2d on MPI ranks against OpenMP threads, side by side on one grid
# (docs/mpi.md; the table in docs/performance.md): the terrain of
# scenarios/runout/runout_terrain_2d.toml on CELL-metre cells (default 1 m:
# 450 x 250), run for DURATION simulated seconds (default 10, series every
# 1 s), as 1 rank x 1 thread, 1 rank x 2 threads and R ranks x 1 thread for
# each R in RANKS (default 2). Prints each run's loop wall time (summary.json
# run.loop_wall_s) and checks every run's series.csv is the first one's,
# byte for byte. Usage: bench/mpi_fv2d.sh [TALUS] [CELL] [DURATION] [RANKS...]
set -euo pipefail
talus=$(realpath "${1:-build/talus}")
cell=${2:-1}
duration=${3:-10}
shift $(( $# < 3 ? $# : 3 ))
ranks=("${@:-2}")
src=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
/usr/bin/python3 "$src/scripts/make_runout_terrain.py" "$tmp/terrain" "$cell"
cat >"$tmp/bench.toml" <<TOML
extends = "$src/scenarios/runout/runout_terrain_2d.toml"
name = "mpi_fv2d"
[run]
duration = $duration
stop_momentum_fraction = 0
[terrain]
file = "terrain/terrain.asc"
obstacles = "terrain/barrier.asc"
[release]
file = "terrain/release.asc"
[output]
series_interval = 1.0
TOML
run() {  # label, ranks, threads
  local out="$tmp/$1"
  if [ "$2" -eq 1 ]; then
    OMP_NUM_THREADS=$3 "$talus" run "$tmp/bench.toml" --quiet --threads "$3" --out "$out" \
      2>"$out.err" || { cat "$out.err"; exit 1; }
  else
    OMP_NUM_THREADS=$3 mpirun -n "$2" --oversubscribe "$talus" run "$tmp/bench.toml" --quiet \
      --threads "$3" --out "$out" 2>"$out.err" || { cat "$out.err"; exit 1; }
  fi
  local wall
  wall=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['run']['loop_wall_s'])" "$out/summary.json")
  local same=first
  [ -n "${first:-}" ] && { cmp -s "$first/series.csv" "$out/series.csv" && same="same series" || same="SERIES DIFFER"; }
  first=${first:-$out}
  printf "%-22s loop %8.2f s   %s\n" "$2 rank(s) x $3 thread(s)" "$wall" "$same"
}
first=""
echo "fv2d on $(awk 'NR == 1 {print $2}' "$tmp/terrain/terrain.asc") x \
$(awk 'NR == 2 {print $2}' "$tmp/terrain/terrain.asc") cells of $cell m, $duration s simulated"
run r1t1 1 1
run r1t2 1 2
for r in "${ranks[@]}"; do run "r${r}t1" "$r" 1; done
