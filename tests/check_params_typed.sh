#!/usr/bin/env bash
# One way to read a parameter (common/params/params.h): a lab keeps the handles it declared and reads through them, a
# choice as its enum. Reading by name (get_float("alpha"), get_text) is for generic code: the panel, sweeps, reports,
# the instructor's yardsticks handed the lab's Params. Prints every read by name in a lab and every choice compared
# with a string literal anywhere, and exits 1, so the old idiom does not creep back.
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"
fail=0
by_name=$(grep -rnE '\.get_(float|int|bool|choice|vec3|file|text)\(' solutions labs --include='*.cpp' --include='*.h' || true)
if [ -n "$by_name" ]; then
  echo "check_params_typed: a lab reads a parameter by name; keep the handle its declaration returns and read that:"
  echo "$by_name"
  fail=1
fi
literal=$(grep -rnE 'get_choice\([^)]*\)[[:space:]]*[!=]=[[:space:]]*"' solutions labs reference support common \
            --include='*.cpp' --include='*.h' 2>/dev/null || true)
if [ -n "$literal" ]; then
  echo "check_params_typed: a choice compared with a string literal, which compiles whatever its spelling; declare it"
  echo "with Params::add_enum and compare with the enum's values:"
  echo "$literal"
  fail=1
fi
exit $fail
