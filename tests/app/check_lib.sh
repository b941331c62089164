# Sourced by tests/app/test_*.sh (not a test itself; the glob in
# tests/CMakeLists.txt only takes test_*.sh). Sets talus and src from the
# script's arguments <talus binary> <source dir>, a temporary folder $tmp
# removed on exit, and counts the checks.
set -uo pipefail
talus=$1 src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0; pass=0
check() {  # name, condition (command)
  if eval "$2"; then pass=$((pass+1)); else echo "FAIL: $1"; fail=$((fail+1)); fi
}
# For a command whose exit status is in $rc (a python heredoc, a run): passes
# when it is 0, otherwise shows its output (file, $tmp/py unless given).
check_rc() {  # name [output file]
  local output=${2:-$tmp/py}
  check "$1" '[ $rc -eq 0 ] || { cat "$output"; false; }'
}
# Last line of a script: the tally, and its exit status.
finish() {  # name of the script's part
  echo "$1: $pass passed, $fail failed"
  [ $fail -eq 0 ]
}
