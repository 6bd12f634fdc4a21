#!/usr/bin/env bash
# Every Catch2 test case must be a ctest entry of its own. catch_discover_tests hands the names to CMake as
# a list: a ';' in a name splits it, and an unbalanced '[' or ']' joins the names after it into one entry
# whose test spec matches nothing, so those tests would "pass" without running.
set -euo pipefail
bad=$("$1" --list-test-names-only | grep -E '[][;]' || true)
if [ -n "$bad" ]; then
  echo "check_test_names: these test names would not run under ctest (no ';', '[' or ']' in names):"
  echo "$bad"
  exit 1
fi
echo "check_test_names: $("$1" --list-test-names-only | grep -c .) test names, each a ctest entry of its own"
