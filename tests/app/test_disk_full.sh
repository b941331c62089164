#!/usr/bin/env bash
# A run that cannot write a file (issue 28 §3): each method stops with exit 1
# and a message naming the file; summary.json says "failed" with the same
# reason; the file is not left cut short and no temporary file remains. The
# disk is "full" for files above a size limit (ulimit -f, SIGXFSZ ignored so
# that a write past it fails with EFBIG as on a full disk): no root, no
# mount. Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"

limited() {  # size limit in KiB, then the talus arguments
  local kib=$1; shift
  (trap '' XFSZ; ulimit -f "$kib"; timeout 120 "$talus" "$@")
}

cannot_write() {  # name, limit (KiB), file the message names, scenario, --set values...
  local name=$1 kib=$2 file=$3 scenario=$4; shift 4
  local out=$tmp/$name
  limited "$kib" run "$scenario" --quiet --out "$out" "$@" >"$tmp/err" 2>&1; rc=$?
  check "$name: exits 1" '[ $rc -eq 1 ] || { cat "$tmp/err"; false; }'
  check "$name: the message names $file" \
    'grep -qF "cannot write '"'"'$out/$file'"'"'" "$tmp/err" || { cat "$tmp/err"; false; }'
  /usr/bin/python3 - "$out/summary.json" "$file" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import json, sys
s = json.load(open(sys.argv[1]))
assert s["status"] == "failed", s["status"]
assert sys.argv[2] in s["error"] and "too large" in s["error"].lower(), s["error"]
PY
  check_rc "$name: summary.json says failed, naming $file"
  check "$name: no cut $file" '[ ! -e "$out/$file" ]'
  check "$name: no temporary file left" '[ -z "$(find "$out" -name "*.tmp")" ]'
}

# fv2d: series.csv (2 kB) fits, the 36 kB result rasters at the end do not.
cannot_write fv2d 20 max_height.npy "$src/scenarios/runout/runout_terrain_2d.toml" \
  --set output.series_interval=10
# DAN: the bed along the path (path.csv, ~40 kB) with the first series row.
cannot_write dan 8 path.csv "$src/scenarios/runout/runout_flume_A.toml"
# DEM and MPM: the first particle snapshot.
cannot_write dem 8 particles_000000.vtu "$src/scenarios/dem/collapse_2d.toml" --set run.duration=0.05
cannot_write mpm 8 particles_000000.vtu "$src/scenarios/mpm/mpm_column_collapse.toml" \
  --set run.duration=0.05

# A disk that stays full: a 200 KiB tmpfs whose free space the run's own
# series.csv (a row every step) uses up. The summary saying why must still fit:
# the run gives up the 64 KiB it held back (.talus-reserve) before writing it.
# Needs to mount (root, as in CI); skipped with a note otherwise.
disk=$tmp/disk
mkdir -p "$disk"
if mount -t tmpfs -o size=200k tmpfs "$disk" 2>/dev/null; then
  trap 'umount "$disk" 2>/dev/null; rm -rf "$tmp"' EXIT
  timeout 300 "$talus" run "$src/scenarios/dem/collapse_2d.toml" --quiet --out "$disk/run" \
    --set run.duration=10 --set output.series_interval=1e-9 --set output.snapshots=false \
    >"$tmp/err" 2>&1; rc=$?
  check "full disk: exits 1" '[ $rc -eq 1 ] || { cat "$tmp/err"; false; }'
  check "full disk: the disk was full" 'grep -q "No space left" "$tmp/err" || { cat "$tmp/err"; false; }'
  /usr/bin/python3 - "$disk/run/summary.json" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import json, sys
s = json.load(open(sys.argv[1]))
assert s["status"] == "failed" and "series.csv" in s["error"], (s["status"], s["error"])
PY
  check_rc "full disk: summary.json says failed, naming series.csv"
  check "full disk: the reserve is gone" '[ ! -e "$disk/run/.talus-reserve" ]'
  umount "$disk"
else
  echo "note: cannot mount a tmpfs here (not root?): the full-disk case is not tried"
fi
finish disk_full
