#!/usr/bin/env bash
# Peer benchmark: talus and LIGGGHTS on the same 3D column collapse
# (../shared/peers/README.md), side by side on this machine.
#
# Usage: bench/peer.sh [NX NY NZ STEPS]      (default 20 10 40 60000)
# Prints one line per run in the peers' format, then the speed ratios.
# Runs: talus 1 thread, talus 2 threads, LIGGGHTS (serial). Each line also
# carries cpu_s, the process's user + system CPU seconds (setup included): on
# a shared, loaded machine the wall-clock time of a run depends on what else
# runs, its CPU time much less, so one-thread comparisons are also given as a
# ratio of CPU seconds. load= is the 1-minute load average before each run.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
nx=${1:-20} ny=${2:-10} nz=${3:-40} steps=${4:-60000}
talus=${TALUS_BIN:-$root/build/talus}
peers=${PEERS_DIR:-$root/../shared/peers}
[ -d "$peers" ] || peers=$root/../../shared/peers  # from a worktree in wt/<name>
work=${BENCH_DIR:-/tmp/talus_bench}
mkdir -p "$work"

read -r lx ly lz Lx Lz t < <(awk -v nx="$nx" -v ny="$ny" -v nz="$nz" -v s="$steps" \
  'BEGIN{a=0.00201; printf "%.10g %.10g %.10g %.10g %.10g %.10g\n", nx*a, ny*a, nz*a, 6*nx*a, 1.5*nz*a, s*5e-6}')

load() { cut -d' ' -f1 /proc/loadavg; }
cpu_of() { awk '{printf "%.2f", $1 + $2}' "$1"; }

run_talus() {  # threads
  local th=$1 out=$work/talus_${nx}x${ny}x${nz}_${steps}_t$1 ld
  ld=$(load)
  /usr/bin/time -f "%U %S" -o "$work/time_t$th" "$talus" run "$root/scenarios/dem/column_collapse.toml" --out "$out" --force --quiet --threads "$th" \
    --set "run.duration=$t" --set "run.domain={min=[0,0,0],max=[$Lx,$ly,$Lz]}" \
    --set "walls.3.point=[0,$ly,0]" --set "particles.0.box={min=[0,0,0],max=[$lx,$ly,$lz]}" \
    --set "output.snapshots=false" --set "output.checkpoint_interval=0" --set "output.series_interval=$t"
  /usr/bin/python3 - "$out/summary.json" "$th" "$(cpu_of "$work/time_t$th")" "$ld" <<'PY'
import json, sys
d = json.load(open(sys.argv[1])); r, m = d["run"], d["metrics"]
print(f"peer=talus particles={m['particles'] + m['particles_removed']} steps={r['steps']} "
      f"wall_s={r['loop_wall_s']:.4f} particle_steps_per_s={r['particle_steps_per_s']:.4g} "
      f"front_x_m={m['front_x_m']} ke_J={m['kinetic_energy_J']} t_sim_s={r['simulated_time_s']} "
      f"erot_J={m['rotational_energy_J']} contacts_per_particle={m['contacts_per_particle']} "
      f"particles_end={m['particles']} threads={sys.argv[2]} cpu_s={sys.argv[3]} load={sys.argv[4]}")
PY
}

pps() { sed -n 's/.*particle_steps_per_s=\([^ ]*\).*/\1/p' <<<"$1"; }
cpu() { sed -n 's/.*cpu_s=\([^ ]*\).*/\1/p' <<<"$1"; }

t1=$(run_talus 1); echo "$t1"
t2=$(run_talus 2); echo "$t2"
if command -v liggghts >/dev/null; then
  ld=$(load)
  lg=$(PEER_OUTDIR=$work /usr/bin/time -f "%U %S" -o "$work/time_lg" \
    bash "$peers/run_peer.sh" liggghts "$nx" "$ny" "$nz" "$steps")
  echo "$lg cpu_s=$(cpu_of "$work/time_lg") load=$ld"
  awk -v a="$(pps "$t1")" -v b="$(pps "$t2")" -v l="$(pps "$lg")" 'BEGIN{
    printf "ratio talus_1thread/liggghts=%.2f talus_2threads/talus_1thread=%.2f talus_2threads/liggghts=%.2f\n", a/l, b/a, b/l}'
  awk -v a="$(cpu "$t1")" -v l="$(cpu_of "$work/time_lg")" 'BEGIN{
    printf "cpu_ratio liggghts_cpu_s/talus_1thread_cpu_s=%.2f\n", l/a}'
else
  echo "liggghts not installed (apt-get install liggghts): peer run skipped"
  awk -v a="$(pps "$t1")" -v b="$(pps "$t2")" 'BEGIN{printf "ratio talus_2threads/talus_1thread=%.2f\n", b/a}'
fi
