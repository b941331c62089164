#!/usr/bin/env bash
# Fuzzes the scenario reader (tests/fuzz/fuzz_scenario.cpp) with libFuzzer,
# under AddressSanitizer and UBSan, for a set time. Seeds: the bundled
# scenarios and the regression inputs in tests/fuzz/regressions/; a
# dictionary of every key the bundled scenarios and docs/scenario-format.md
# name. A finding (crash, hang over 10 s, sanitizer report, an exception other
# than InputError, a resolved scenario that does not read back) stops the run
# and is saved under <build>/fuzz-findings/; add it to tests/fuzz/regressions/
# once fixed. Usage: scripts/fuzz.sh [seconds=3600]
set -euo pipefail
seconds=${1:-3600}
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_FUZZ:-$root/build-fuzz}
TALUS_WITH_FUZZ=1 bash "$root/scripts/install-deps.sh"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DTALUS_FUZZ=ON -DTALUS_NO_CUDA=ON >/dev/null
cmake --build "$build" -j "$(nproc)" --target fuzz_scenario >/dev/null

seeds=$build/fuzz-seeds corpus=$build/fuzz-corpus findings=$build/fuzz-findings
mkdir -p "$seeds" "$corpus" "$findings"
cp "$root"/scenarios/*/*.toml "$root"/tests/fuzz/regressions/* "$seeds"/
# Keys as dictionary words: `name =` at the start of a line, and `[table]` headers.
{
  cat "$root"/scenarios/*/*.toml "$root"/docs/scenario-format.md |
    grep -oE '^\s*`?[a-z_0-9]+`? *=' | tr -d ' `=' | sort -u | sed 's/.*/"&"/'
  cat "$root"/scenarios/*/*.toml | grep -oE '^\[\[?[a-z_.0-9]+\]\]?' | sort -u | sed 's/.*/"&"/'
} >"$build/fuzz.dict"

cd "$build"
echo "fuzzing the scenario reader for ${seconds} s; findings go to $findings" >&2
ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=0 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  ./tests/fuzz/fuzz_scenario -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
  -max_len=16384 -dict="$build/fuzz.dict" -artifact_prefix="$findings/" \
  -print_final_stats=1 "$corpus" "$seeds"
