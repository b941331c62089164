#!/usr/bin/env bash
# Everything issue 35 checks on a machine with a GPU, in one script that ends in
# a few minutes: the DEM verification cases and backend tests on the GPU, a
# compute-sanitizer pass over a short case, then bench/gpu_peer.sh.
# The binaries are built beforehand wherever nvcc is (make build; CMake finds
# nvcc and builds for sm_90): build/tests/test_dem_gpu and
# build/bench/bench_gpu_peer link the DEM layers alone, so the GPU machine needs
# no GDAL or MPI; libraries it lacks (libfmt) may sit in .gpu-libs/.
# Usage: bench/gpu_check.sh [BUILD_DIR]   Results also go to $OUT (or /tmp/talus_gpu_check).
set -uo pipefail
build=${1:-build}
out=${OUT:-/tmp/talus_gpu_check}
mkdir -p "$out"
[ -d .gpu-libs ] && export LD_LIBRARY_PATH=$PWD/.gpu-libs:${LD_LIBRARY_PATH:-}
{
  date -u
  nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv
  lscpu | grep -E "^Model name|^CPU\(s\)"
} 2>&1 | tee "$out/device.txt"
echo "== GPU tests"
TALUS_TEST_BACKEND=gpu timeout 150 "$build/tests/test_dem_gpu" >"$out/tests.txt" 2>&1
echo "test_dem_gpu exit $?"
grep -E "^\[  (FAILED|PASSED|SKIPPED) |\[gpu\]|Failure|Expected|Which is|actual" "$out/tests.txt" | head -60
if command -v compute-sanitizer >/dev/null; then
  echo "== compute-sanitizer (memcheck) on two short cases"
  TALUS_TEST_BACKEND=gpu timeout 40 compute-sanitizer --tool memcheck --print-limit 5 \
    "$build/tests/test_dem_gpu" --gtest_filter='HertzImpact/1.ChungOoiCase2*:GpuBackend.Scenarios*' \
    >"$out/sanitizer.txt" 2>&1
  echo "compute-sanitizer exit $?"
  grep -E "ERROR SUMMARY|PASSED|FAILED|Invalid" "$out/sanitizer.txt" | head -10
fi
echo "== bench/gpu_peer.sh"
timeout 240 bash bench/gpu_peer.sh "$build" 2>&1 | tee "$out/bench.txt"
date -u
