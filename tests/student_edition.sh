#!/usr/bin/env bash
# The student edition works: `scripts/kit export-student` leaves out solutions/, reference/, tests/ and grader/hidden/;
# --labs refuses a lab whose starter holds an unreleased lab's answers (labs/README.md); the
# export configures and builds on its own; its self-check (golden references) gives the shipped lab01 starter 0
# points and the reference solution, copied into the export's labs/, full marks. Slow: it builds the export
# (lab01 and gsv-grade only, 2 cores). Exit 0: pass, 1: fail.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gsv-student-edition.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
kit=$tmp/export
log=$tmp/log
unset GSV_ROOT  # the labs must find their shaders in the export, not wherever this points
start=$SECONDS

fail() {
  echo "student_edition: FAIL: $*" >&2
  if [ -s "$log" ]; then echo "--- last output:" >&2; tail -n 40 "$log" >&2; fi
  exit 1
}
step() { echo "student_edition: [$((SECONDS - start))s] $*"; }
run() { "$@" >"$log" 2>&1; }

# The export. Untracked files too: this tests the working tree, new files not yet committed included.
step "export"
run "$root/scripts/kit" export-student --include-untracked "$kit" || fail "scripts/kit export-student failed"
tail -n 1 "$log"
for p in solutions reference tests grader/hidden build grade-results .git; do
  [ ! -e "$kit/$p" ] || fail "$p was exported"
done
grep -q "later labs' starters hold earlier labs' answers" "$log" || fail "a full export does not say that later labs hold earlier answers"
for p in labs/lab01_gooch grader/golden/lab01 grader/cases/lab01.json README.md .github/workflows/self-check.yml \
         grader/ci/classroom_points.py; do
  [ -e "$kit/$p" ] || fail "$p is missing from the export"
done
# The golden arrays (<case>.<array>.f32s) ship with the golden images: the self-check checks a lab's numbers too.
while IFS= read -r -d '' f; do
  rel=${f#"$root"/}
  [ -e "$kit/$rel" ] || fail "$rel is missing from the export"
done < <(find "$root/grader/golden" -name '*.f32s' -print0)
grep -q "scripts/kit grade" "$kit/.ci/run" || fail ".ci/run of the export does not run the self-check"
# Its own README: two commands that work here, none that need what it lacks.
grep -q "^scripts/kit grade  " "$kit/README.md" || fail "the export's README does not give 'scripts/kit grade'"
grep -q "^scripts/kit grade --todo L01-T3" "$kit/README.md" || fail "the export's README does not give the per-TODO check"
! grep -q "scripts/kit test" "$kit/README.md" || fail "the export's README names 'scripts/kit test', which it cannot run"
# Lab sheets and decks that point at nothing the edition lacks.
if grep -n "_solution\|tests/test_\|solutions/\|^## For the instructor\|: its answer |" "$kit"/labs/*/README.md; then
  fail "a lab sheet points at the reference or the tests, or keeps the instructor's section (above)"
fi
python3 - "$kit" <<'PY' || fail "a deck embeds a figure the edition has not got (above)"
import os, re, sys
root = sys.argv[1]
missing = []
for name in sorted(os.listdir(os.path.join(root, "slides"))):
    if name.endswith(".md"):
        for m in re.finditer(r"!\[[^\]]*\]\(([^)\s]+)\)", open(os.path.join(root, "slides", name), encoding="utf-8").read()):
            if not os.path.exists(os.path.normpath(os.path.join(root, "slides", m.group(1)))):
                missing.append(f"slides/{name}: {m.group(1)}")
print("\n".join(missing))
sys.exit(1 if missing else 0)
PY
if ! { [ -x "$kit/.ci/run" ] && [ -x "$kit/scripts/kit" ]; }; then fail "scripts lost their executable bit"; fi

# Week by week: a lab goes out only with the labs whose answers its starter holds (labs/README.md's table).
step "export --labs"
run "$root/scripts/kit" export-student --labs lab01,lab03 "$tmp/week3" && fail "--labs lab01,lab03 was not refused (lab03 holds lab02's answers)"
grep -q "lab03's starter holds lab02's answers (lic_time.frag): release lab02 too" "$log" ||
  fail "no clear message for releasing lab03 without lab02"
[ ! -e "$tmp/week3/labs" ] || fail "a refused --labs export left files behind"
run "$root/scripts/kit" export-student --labs lab01,lab02,lab03 "$tmp/week3" || fail "--labs lab01,lab02,lab03 failed"
for p in labs/lab03_texture_arrays grader/cases/lab02.json grader/golden/lab03; do
  [ -e "$tmp/week3/$p" ] || fail "--labs lab01,lab02,lab03 left out $p"
done
for p in labs/lab04_terrain grader/cases/lab04.json grader/golden/lab07 reference; do
  [ ! -e "$tmp/week3/$p" ] || fail "--labs lab01,lab02,lab03 exported $p"
done

# DEST must be new or empty, and outside the kit.
run "$root/scripts/kit" export-student "$kit" && fail "exporting into a non-empty folder was not refused"
grep -q "not empty" "$log" || fail "no clear message for a non-empty DEST"
run "$root/scripts/kit" export-student "$root/build-student-export-test" && fail "exporting into the kit was not refused"
[ ! -e "$root/build-student-export-test" ] || fail "a refused export left $root/build-student-export-test behind"

# Configure and build the export on its own: no solutions/, no tests/.
# The README's per-TODO command, as written: set-up, configure, build lab01 and the grader only, self-check one TODO.
step "scripts/kit grade --todo L01-T1 in the export"
(cd "$kit" && run scripts/kit grade --todo L01-T1) || fail "the export's 'scripts/kit grade --todo L01-T1' failed"
python3 - "$kit/build/grade-results/results.json" <<'PY' || fail "the per-TODO self-check graded other TODOs, or gave the starter points"
import json, sys
tests = json.load(open(sys.argv[1]))["tests"]
bad = [t["name"] for t in tests if "L01-T1" not in t.get("tags", []) or float(t["score"]) != 0]
print(f"{len(tests)} checks of L01-T1, all 0 points" if tests and not bad else f"checks: {[t['name'] for t in tests]}, wrong: {bad}")
sys.exit(0 if tests and not bad else 1)
PY
[ ! -e "$kit/build/bin/lab01_solution" ] || fail "the export built lab01_solution"

# Grades the export's labs (self-check, as a student would) into $1 and checks results.json (Gradescope shape;
# report.json, where written, for the mode): $2 = zero (every check 0 points) or full (every check full marks).
grade() {
  local out=$1 expect=$2 rc=0
  run "$kit/build/bin/gsv-grade" --kit "$kit" --bin "$kit/build/bin" --out "$out" --labs lab01 || rc=$?
  [ $rc -eq 0 ] || fail "gsv-grade exited $rc on the $expect run"
  python3 - "$out" "$expect" <<'PY' || fail "the $expect run's results are wrong (above)"
import json, os, sys

out, expect = sys.argv[1], sys.argv[2]
problems = []
results = json.load(open(os.path.join(out, "results.json")))
tests = results.get("tests", [])
score = float(results.get("score", -1))
top = sum(float(t.get("max_score", 0)) for t in tests)
if not tests or top <= 0:
    problems.append(f"no graded checks in results.json ({len(tests)} tests, {top:g} points)")
for t in tests:
    if t.get("visibility") in ("after_due_date", "hidden"):
        problems.append(f"hidden check in a self-check: {t.get('name')}")
    s, m = float(t.get("score", 0)), float(t.get("max_score", 0))
    if (expect == "zero" and s != 0) or (expect == "full" and s < m):
        first = str(t.get("output", "")).strip().splitlines()[:3]
        problems.append(f"{t.get('name')}: {s:g} / {m:g}: " + " | ".join(first))
if expect == "zero" and score != 0:
    problems.append(f"score {score:g}, expected 0")
if expect == "full" and abs(score - top) > 1e-9:
    problems.append(f"score {score:g}, expected the maximum {top:g}")

# The mode: self-check against golden images (there is no reference solution in the student edition).
def find(node, key, found):
    if isinstance(node, dict):
        for k, v in node.items():
            if k == key and isinstance(v, str):
                found.append(v)
            find(v, key, found)
    elif isinstance(node, list):
        for v in node:
            find(v, key, found)
    return found
mode = "no report.json; golden references, as no lab01_solution was built"
report_path = os.path.join(out, "report.json")
if os.path.exists(report_path):
    report = json.load(open(report_path))
    modes = [report["mode"]] if isinstance(report, dict) and isinstance(report.get("mode"), str) else find(report, "mode", [])
    references = set(find(report, "reference", []))
    if modes and any(m != "self-check" for m in modes):
        problems.append(f"mode {modes}, expected self-check")
    if references - {"golden"}:
        problems.append(f"references {sorted(references)}, expected golden only")
    mode = f"mode {modes[0] if modes else '?'}, references {sorted(references) or '?'}"
for p in problems:
    print("  " + p)
print(f"student_edition: {expect}: {score:g} / {top:g} points over {len(tests)} checks ({mode})")
sys.exit(1 if problems else 0)
PY
}

step "self-check the starter"
grade "$tmp/grade-starter" zero

step "copy solutions/lab01_gooch into the export's labs/, rebuild lab01"
cp "$root"/solutions/lab01_gooch/* "$kit/labs/lab01_gooch/"
run cmake --build "$kit/build" --target lab01 -j 2 || fail "the export does not build with the solution in labs/"
step "self-check the solution"
grade "$tmp/grade-solution" full

step "a known mistake in L01-T1, self-checked: the shipped pictures name it"
# The export has no tests/ and no solutions: what names the mistake is grader/golden/lab01/mistakes.* alone.
[ ! -d "$kit/tests" ] && [ -f "$kit/grader/golden/lab01/mistakes.json" ] || fail "the export lacks the shipped mistakes, or has tests/"
says=$(python3 - "$root/tests/mutants/lab01.json" "$kit/labs/lab01_gooch" <<'PY'
import json, sys
spec = json.load(open(sys.argv[1]))
m = next(m for m in spec["mutants"] if m["name"] == "the normal left in the model's space")
path = f"{sys.argv[2]}/{m['file']}"
text = open(path).read()
assert m["find"] in text, f"{m['name']}: its edit does not apply"
open(path, "w").write(text.replace(m["find"], m["replace"], 1))
print(m["says"])
PY
) || fail "cannot make lab01's L01-T1 mistake in the export"
run cmake --build "$kit/build" --target lab01 -j 2 || fail "the export does not build with the mistake"
rc=0
run "$kit/build/bin/gsv-grade" --kit "$kit" --bin "$kit/build/bin" --out "$tmp/grade-mistake" --labs lab01 || rc=$?
[ $rc -le 1 ] || fail "gsv-grade exited $rc on the mistake"
grep -qF "$says" "$tmp/grade-mistake/results.json" ||
  fail "results.json of the L01-T1 mistake does not say what went wrong ('$says')"
python3 -c 'import html, sys; sys.exit(sys.argv[2] not in html.unescape(open(sys.argv[1]).read()))' \
  "$tmp/grade-mistake/report.html" "$says" || fail "report.html of the L01-T1 mistake does not say what went wrong"
size=$(stat -c %s "$tmp/grade-mistake/report.html")
[ "$size" -lt 2000000 ] || fail "the student's report.html is $size bytes, not well under 2 MB"
echo "the student's report.html: $size bytes"

step "passed"
