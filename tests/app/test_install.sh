#!/usr/bin/env bash
# make install's rule (cmake --install): the binary into PREFIX/bin and, where
# the build has it, the Python package into PREFIX/lib/python3/dist-packages,
# importable from there without the build tree.
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
build=$(dirname "$talus")
cmake --install "$build" --prefix "$tmp/prefix" >"$tmp/log" 2>&1; rc=$?
check_rc "cmake --install succeeds" "$tmp/log"
check "the binary is installed and runs" '"$tmp/prefix/bin/talus" --version >/dev/null'
if [ -d "$build/python/talus" ]; then
  ( cd "$tmp" && PYTHONPATH="$tmp/prefix/lib/python3/dist-packages" /usr/bin/python3 -c "
import talus, os, sys
assert talus.__file__.startswith(sys.argv[1]), talus.__file__
print(talus.validate(sys.argv[2]))" "$tmp/prefix" "$src/scenarios/dem/collapse_2d.toml" ) >"$tmp/py" 2>&1; rc=$?
  check_rc "the installed package imports and validates a scenario"
fi
finish install
