#!/usr/bin/env bash
# A student's build cannot see the instructor's yardsticks in reference/: the kit's exported targets
# (gsv-targets.cmake, what the grader's submission project links) have no gsv_reference; the grader's sandbox
# allow-lists (grader/src/grade/walls.cpp, set_up_sandbox) name no reference/ folder; and the submission project,
# configured against this build with the reference solutions as a submission's labs/, has no gsv_reference target,
# compiles no lab with GSV_HAVE_REFERENCE and reads no file under reference/. (That reference/ is not exported is
# student_edition.sh's; that no shipped layer includes it, check_layout.sh's.)
#   check_reference_unseen.sh KIT_ROOT KIT_BUILD     Exit 0: pass, 1: fail.
set -euo pipefail
root=$(cd "$1" && pwd -P)
build=$(cd "$2" && pwd -P)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gsv-reference-unseen.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "check_reference_unseen: FAIL: $*" >&2; exit 1; }

[ -d "$root/reference" ] || fail "no reference/ in $root"
[ -f "$build/gsv-targets.cmake" ] || fail "$build has no gsv-targets.cmake: build the kit first"
! grep -n "gsv_reference" "$build/gsv-targets.cmake" || fail "gsv-targets.cmake exports gsv_reference (above)"

# The two allow-lists of set_up_sandbox, from "void GradingSession::set_up_sandbox" to the first line after them.
sandbox=$(sed -n '/^void GradingSession::set_up_sandbox/,/build_policy_.read_write/p' "$root/grader/src/grade/walls.cpp")
grep -q "build_policy_.read_only" <<<"$sandbox" || fail "cannot find the build allow-list in grader/src/grade/walls.cpp's set_up_sandbox"
! grep -n "reference\"\|reference()" <<<"$sandbox" || fail "set_up_sandbox lets student code read reference/ (above)"

# The submission project as the grader configures it, the reference solutions standing in for a student's labs.
mkdir -p "$tmp/kit/labs"
cp -R "$root"/solutions/* "$tmp/kit/labs/"
generator=$(sed -n 's/^CMAKE_GENERATOR:INTERNAL=//p' "$build/CMakeCache.txt")
cmake -S "$root/grader/submission" -B "$tmp/build" -DGSV_KIT_BUILD="$build" -DGSV_LABS_ROOT="$tmp/kit" \
      ${generator:+-G "$generator"} >"$tmp/configure.log" 2>&1 || { cat "$tmp/configure.log" >&2; fail "configuring the submission project failed"; }
targets=$(cmake --build "$tmp/build" --target help 2>&1) || fail "cannot list the submission build's targets"
grep -q "lab07" <<<"$targets" || fail "the submission build has no lab targets: $targets"
! grep -n "gsv_reference" <<<"$targets" || fail "the submission build has a gsv_reference target (above)"
! grep -rln "GSV_HAVE_REFERENCE\|$root/reference/" "$tmp/build" --include='*.ninja' --include='Makefile' --include='*.make' \
      --include='flags.make' || fail "the submission build compiles with GSV_HAVE_REFERENCE or reads reference/ (files above)"
echo "check_reference_unseen: no gsv_reference in gsv-targets.cmake, the sandbox's allow-lists or the submission build" \
     "($(grep -c '^[^#]' <<<"$targets") targets)"
