#!/usr/bin/env bash
# The kit's layering (CONTRIBUTING.md): the framework in common/ stands in folders by concern and knows nothing
# of the labs' domain code (support/), the labs, their solutions or the grader; support/ knows nothing of the
# labs or the grader. Prints every breach and exits 1, so a newcomer's shortcut is caught where it is made.
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"
fail=0
breach() { echo "check_layout: $*"; fail=1; }

loose=$(find common support -maxdepth 1 -type f ! -name CMakeLists.txt ! -name README.md)
[ -z "$loose" ] || breach "files standing directly in common/ or support/ (put each in the folder of its concern): $loose"

inward=$(grep -rnE '#include "(support|labs|solutions|grader|tests)/' common || true)
[ -z "$inward" ] || breach "the framework includes domain, lab or grader code:"$'\n'"$inward"
outward=$(grep -rnE '#include "(labs|solutions|grader|tests)/' support || true)
[ -z "$outward" ] || breach "support/ includes lab or grader code:"$'\n'"$outward"

# A lab's own file names (its shaders, its C++) have no business in the framework, not even in a comment.
names=$(find solutions -mindepth 2 -maxdepth 2 -type f ! -name lab.cpp ! -name README.md -printf '%f\n' | sort -u)
for name in $names; do
  hits=$(grep -rnwF "$name" common || true)
  [ -z "$hits" ] || breach "the framework names lab file '$name':"$'\n'"$hits"
done
[ $fail -eq 0 ] && echo "check_layout: common/ and support/ keep to their layers ($(find common -name '*.cpp' -o -name '*.h' | wc -l) framework files, $(find support -name '*.cpp' -o -name '*.h' | wc -l) support files)"
exit $fail
