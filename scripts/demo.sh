#!/usr/bin/env bash
# make demo: runs the flagship scenario (the Mancarella & Hungr flume, geometry
# A, Kuen's Model 3) on its defaults and shows where the results and plots are.
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/runs/demo-flume_A_model3
echo "talus demo: flume geometry A, Kuen Model 3 (9099 disks, 3 s of flow) -> $out"
# The demo owns this folder: it is replaced on every `make demo` (removed
# first: --force refuses a folder left by a killed demo or an older talus).
rm -rf "$out"
"$root/$build/talus" run "$root/scenarios/dem/flume_A_model3.toml" --out "$out" --threads "$(nproc)"
echo
echo "results:   $out/summary.json (\"flume\": arrival, run-up, deposit tail, wall forces)"
echo "           $out/flume/front.csv, $out/flume/deposit_profile.csv, $out/series.csv"
echo "ParaView:  $out/particles.pvd (field \"layer\") and $out/walls.pvd"
echo "plots:"
/usr/bin/python3 "$root/plots/plot.py" "$out" | sed 's/^/  /'
