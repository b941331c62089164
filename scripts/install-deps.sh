#!/usr/bin/env bash
# Installs the Debian packages talus needs to build, test and plot. Idempotent:
# does nothing when everything is already there. Needs root (or sudo) only when
# something is missing.
set -euo pipefail
pkgs=(cmake g++ make libeigen3-dev libtomlplusplus-dev libcli11-dev libfmt-dev
      nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev libgdal-dev voro++-dev
      libnlopt-dev libopenmpi-dev openmpi-bin
      python3 python3-vtk9 python3-matplotlib python3-numpy
      python3-dev pybind11-dev python3-pytest python3-pandas python3-scipy)
# The peer benchmarks need LIGGGHTS (bench/peer.sh) and Gerris (bench/gerris_dam_break.py).
[ "${TALUS_WITH_PEERS:-0}" = 1 ] && pkgs+=(liggghts gerris)
# The scenario reader's fuzzer needs clang's libFuzzer and OpenMP; only scripts/fuzz.sh asks for it.
[ "${TALUS_WITH_FUZZ:-0}" = 1 ] && pkgs+=(clang libomp-dev)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "talus: installing Debian packages: ${missing[*]}" >&2
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
