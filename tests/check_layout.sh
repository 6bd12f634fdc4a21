#!/usr/bin/env bash
# The kit's layering (CONTRIBUTING.md): the framework in common/ stands in folders by concern and knows nothing
# of the labs' domain code (support/), the labs, their solutions or the grader; support/ knows nothing of the
# labs (their files' names included) or the grader. Neither knows the instructor's yardsticks in reference/, nor do the grader and the tools
# (all four ship in the student edition, which has no reference/); reference/ builds on common/ and support/, and
# a lab never names it: its sweep plan, reference/<lab dir>/sweep_plan.cpp, reaches the lab through the lab's
# sweep_view.h, and only the solution target links it, so the starters, the student edition and the grader's
# submission build compile without it and a student's file holds no #ifdef for it. Prints every breach and exits 1,
# so a newcomer's shortcut is caught where it is made.
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"
fail=0
breach() { echo "check_layout: $*"; fail=1; }

loose=$(find common support -maxdepth 1 -type f ! -name CMakeLists.txt ! -name README.md)
[ -z "$loose" ] || breach "files standing directly in common/ or support/ (put each in the folder of its concern): $loose"
# The grader's code stands in grader/src/<concern>/, apart from its data (cases/, hidden/, golden/), its CI templates
# and the project that builds a submission.
astray=$(find grader \( -name '*.cpp' -o -name '*.h' \) | grep -vE '^grader/src/[a-z_]+/[^/]+$' || true)
[ -z "$astray" ] || breach "grader code outside grader/src/<concern>/ (put each in the folder of its concern): $astray"

inward=$(grep -rnE '#include "(support|reference|labs|solutions|grader|tests)/' common || true)
[ -z "$inward" ] || breach "the framework includes domain, reference, lab or grader code:"$'\n'"$inward"
outward=$(grep -rnE '#include "(reference|labs|solutions|grader|tests)/' support || true)
[ -z "$outward" ] || breach "support/ includes reference, lab or grader code:"$'\n'"$outward"
shipped=$(grep -rnE '#include "reference/' grader tools 2>/dev/null || true)
[ -z "$shipped" ] || breach "the grader or a tool includes reference/, which the student edition has not got:"$'\n'"$shipped"
if [ -d reference ]; then
  upward=$(grep -rnE '#include "(labs|solutions|grader|tests)/' reference || true)
  [ -z "$upward" ] || breach "reference/ includes lab, grader or test code by path (a lab's own headers are found by name):"$'\n'"$upward"
fi
# A lab names neither reference/ nor the switch its solution build links it with: no #include "reference/...", no
# GSV_HAVE_REFERENCE.
named=$(grep -rnE '#[ \t]*include[ \t]+"reference/|GSV_HAVE_REFERENCE' solutions labs --include='*.cpp' --include='*.h' || true)
[ -z "$named" ] || breach "a lab names the instructor's reference/ (its sweep plan goes in reference/<lab dir>/sweep_plan.cpp):"$'\n'"$named"

# Floors (CONTRIBUTING.md, "Floors"): within common/ and within grader/src/ a folder includes only its own folder and
# those on the floors below it, so the shared words stand on the ground floor and nothing low reaches up, or sideways,
# for a type. The floors are read from CONTRIBUTING.md, so its map and the tree cannot part: a folder on no floor, or a
# floor naming a folder the tree has not got, is a breach too.
floors_of() {  # "folder floor" lines for the numbered list under "`$1/`, from the ground up:"
  awk -v heading="\`$1/\`, from the ground up:" '
    $0 == heading { on = 1; next }
    !on { next }
    /^[0-9]+\. / { floor++; head = $0; sub(/: .*/, "", head)
                   while (match(head, /`[a-z_]+\/`/)) {
                     print substr(head, RSTART + 1, RLENGTH - 3), floor
                     head = substr(head, RSTART + RLENGTH)
                   }
                   next }
    floor && /^   / { next }
    floor { exit }' CONTRIBUTING.md
}
check_floors() {
  local root=$1 table listed present
  table=$(floors_of "$root")
  if [ -z "$table" ]; then
    breach "CONTRIBUTING.md lists no floors of $root/ (a line \"\`$root/\`, from the ground up:\" and a numbered list)"
    return
  fi
  listed=$(echo "$table" | cut -d' ' -f1 | sort)
  present=$(find "$root" -mindepth 1 -maxdepth 1 -type d -printf '%f\n' | sort)
  local unplaced gone
  unplaced=$(comm -13 <(echo "$listed") <(echo "$present") | tr '\n' ' ')
  [ -z "$unplaced" ] || breach "folders of $root/ on no floor of CONTRIBUTING.md (put each on one): $unplaced"
  gone=$(comm -23 <(echo "$listed") <(echo "$present") | tr '\n' ' ')
  [ -z "$gone" ] || breach "CONTRIBUTING.md's floors of $root/ name folders it has not got: $gone"
  local upward
  upward=$(grep -rnE "^[[:space:]]*#[[:space:]]*include[[:space:]]+\"$root/[a-z_]+/" "$root" |
           awk -v root="$root" -v table="$table" '
    BEGIN { n = split(table, rows, "\n"); for (i = 1; i <= n; i++) { split(rows[i], f, " "); floor[f[1]] = f[2] } }
    { file = $0; sub(/:.*/, "", file); split(substr(file, length(root) + 2), p, "/"); from = p[1]
      to = $0; sub(/^[^"]*"/, "", to); split(substr(to, length(root) + 2), q, "/"); to = q[1]
      if (to == from || !(from in floor) || !(to in floor)) next
      if (floor[to] > floor[from]) print $0 "   (" from "/ is on floor " floor[from] ", " to "/ above it on " floor[to] ")"
      else if (floor[to] == floor[from]) print $0 "   (" from "/ and " to "/ share floor " floor[from] ")" }' || true)
  [ -z "$upward" ] || breach "$root/ includes upward or sideways (move what it needs down a floor: CONTRIBUTING.md, \"Floors\"):"$'\n'"$upward"
}
check_floors common
check_floors grader/src

# A lab's own file names (its shaders, its C++) have no business in the framework or the shared domain code, not even
# in a comment: a lab's module table (lab 06's raycast_modules.cpp) names its files, and support/ generates from it.
# Every lab's lab.cpp, README.md and lab.json (its description: cmake/lab_list.cmake) are the kit's names, not a lab's.
names=$(find solutions -mindepth 2 -maxdepth 2 -type f ! -name lab.cpp ! -name README.md ! -name lab.json -printf '%f\n' | sort -u)
for name in $names; do
  hits=$(grep -rnwF "$name" common support || true)
  [ -z "$hits" ] || breach "the framework or support/ names lab file '$name':"$'\n'"$hits"
done
[ $fail -eq 0 ] && echo "check_layout: common/, support/ and reference/ keep to their layers, common/ and grader/src/ to their floors ($(find common -name '*.cpp' -o -name '*.h' | wc -l) framework files, $(find support -name '*.cpp' -o -name '*.h' | wc -l) support files, $(find reference -name '*.cpp' -o -name '*.h' 2>/dev/null | wc -l) reference files)"
exit $fail
