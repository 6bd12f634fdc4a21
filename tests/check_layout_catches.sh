#!/usr/bin/env bash
# The floor check of tests/check_layout.sh can fail: in a copy of the kit's code and CONTRIBUTING.md it passes, and each
# breach planted in the copy (an include upward, one sideways, in common/ and in grader/src/; a folder on no floor; a
# floor whose folder is gone; a lab that names reference/) fails it with a line naming the breach. Without this, a check that had stopped reading
# the floors would pass on every tree.
set -euo pipefail
kit=$(cd "${1:-$(dirname "$0")/..}" && pwd)
check="$kit/tests/check_layout.sh"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail=0

copy() {  # the files check_layout.sh reads: the code of each part, the two folders' own files, CONTRIBUTING.md
  rm -rf "$scratch/kit"
  mkdir -p "$scratch/kit"
  (cd "$kit" && find common support grader solutions labs reference tools \( -name '*.cpp' -o -name '*.h' \
     -o -name CMakeLists.txt -o -name README.md \) -type f -print0 2>/dev/null | tar --null -T - -cf -) |
    tar -xf - -C "$scratch/kit"
  cp "$kit/CONTRIBUTING.md" "$scratch/kit/"
}
# expect NAME WORDS...: check_layout.sh on the copy fails and its output holds WORDS.
expect() {
  local name=$1 words=$2 out
  if out=$("$check" "$scratch/kit" 2>&1); then
    echo "check_layout_catches: $name: check_layout.sh passed"
    fail=1
  elif ! grep -qF -- "$words" <<<"$out"; then
    echo "check_layout_catches: $name: check_layout.sh failed without saying \"$words\":"$'\n'"$out"
    fail=1
  fi
}

copy
if ! out=$("$check" "$scratch/kit" 2>&1); then
  echo "check_layout_catches: the unchanged copy fails already:"$'\n'"$out"
  exit 1
fi

echo '#include "grader/src/judge/array_compare.h"' >>"$scratch/kit/grader/src/run/process.h"
expect "run/ reaching judge/" "grader/src/run/process.h"
copy
echo '#include "grader/src/grade/grade.h"' >>"$scratch/kit/grader/src/core/case_status.h"
expect "core/ reaching grade/" "core/ is on floor 1, grade/ above it"
copy
echo '#include "grader/src/margins/margins.h"' >>"$scratch/kit/grader/src/lms/lms_export.h"
expect "lms/ reaching margins/ beside it" "lms/ and margins/ share floor"
copy
echo '#include "common/shader/shader_program.h"' >>"$scratch/kit/common/gl/buffer.h"
expect "gl/ reaching shader/" "gl/ is on floor 4, shader/ above it"
copy
echo '#include "common/app/app.h"' >>"$scratch/kit/common/window/image_view.h"
expect "window/ reaching app/" "common/window/image_view.h"
copy
echo '#include "common/shader/shader_program.h"' >>"$scratch/kit/common/timing/timing.h"
expect "timing/ reaching shader/ beside it" "timing/ and shader/ share floor"
copy
mkdir "$scratch/kit/grader/src/extra"
echo '#pragma once' >"$scratch/kit/grader/src/extra/extra.h"
expect "a folder on no floor" "on no floor of CONTRIBUTING.md (put each on one): extra"
copy
rm -r "$scratch/kit/common/timing"
expect "a floor whose folder is gone" "name folders it has not got: timing"
copy
printf '#ifdef GSV_HAVE_REFERENCE\n#include "reference/lab02_lic/exact_lic_images.h"\n#endif\n' >>"$scratch/kit/solutions/lab02_lic/lab.cpp"
expect "a lab naming reference/ behind its switch" "solutions/lab02_lic/lab.cpp:"
copy
sed -i 's/^`grader\/src\/`, from the ground up:$/The grader'"'"'s floors:/' "$scratch/kit/CONTRIBUTING.md"
expect "no floors written" "CONTRIBUTING.md lists no floors of grader/src/"

[ $fail -eq 0 ] && echo "check_layout_catches: every planted breach of the floors fails check_layout.sh"
exit $fail
