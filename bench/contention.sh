#!/usr/bin/env bash
# One thread against two on the peer column, on a quiet machine and with one
# competing busy process (`yes > /dev/null`), as a user with something else
# running would see it. Runs alternate (1, 2, 1, 2, ...) so that drifts of a
# shared machine hit both alike; prints each run and the median loop seconds.
# Usage: bench/contention.sh BIN [REPEATS] [STEPS]   (default 5, 15000)
# Target (issue 28): with one busy process, two threads at least as fast as one.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$1 repeats=${2:-5} steps=${3:-15000}
busy=""
trap '[[ -n $busy ]] && kill "$busy" 2>/dev/null || true' EXIT

median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

run_set() {  # label
  local label=$1 t1="" t2=""
  for ((r = 0; r < repeats; ++r)); do
    for th in 1 2; do
      s=$("$root/bench/peer_talus.sh" "$bin" "$th" "$steps" | sed -E 's/.*loop_s=([0-9.]+).*/\1/')
      echo "$label threads=$th run=$r loop_s=$s"
      if [[ $th == 1 ]]; then t1+="$s"$'\n'; else t2+="$s"$'\n'; fi
    done
  done
  m1=$(printf '%s' "$t1" | median) m2=$(printf '%s' "$t2" | median)
  awk -v l="$label" -v a="$m1" -v b="$m2" \
    'BEGIN{printf "%s: median loop_s one thread %.2f, two threads %.2f, speed-up %.2f\n", l, a, b, a/b}'
}

run_set quiet
yes > /dev/null &
busy=$!
run_set "one busy process"
