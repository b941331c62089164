#!/usr/bin/env bash
# make demo: runs the bundled flagship scenario on its defaults and shows where
# the results and plots are. (The column collapse until the flume scenario lands.)
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/runs/demo-column_collapse
echo "talus demo: 3D column collapse (8000 spheres, 0.3 s) -> $out"
# The demo owns this folder: it is replaced on every `make demo`.
"$root/$build/talus" run "$root/scenarios/column_collapse.toml" --out "$out" --force --threads "$(nproc)"
echo
echo "results:   $out/summary.json, $out/series.csv"
echo "ParaView:  $out/particles.pvd and $out/walls.pvd"
echo "plots:"
/usr/bin/python3 "$root/plots/plot_run.py" "$out" | sed 's/^/  /'
