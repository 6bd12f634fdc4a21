#!/usr/bin/env bash
# The Gradescope autograder (scripts/kit gradescope): the zip holds setup.sh and run_autograder at its top (both
# executable), the solutions and hidden cases, and no slides, tests or build; run_autograder, run in a simulated
# Gradescope layout (source/ = the unzipped autograder, submission/ = a student's files, results/), writes
# results.json in Gradescope's format for the lab 01 starter (a repository: labs/ at the top) and the solution (a
# zip of one folder holding labs/): tests with name, score, max_score and output, and a total that is their sum,
# full marks for the solution, hidden cases included. grader/ci/classroom_points.py turns the same results into
# GitHub Classroom points. The simulated source/ reuses this build (setup.sh's build is not rerun), so the grading
# takes the kit this build was made from (the working tree), not the zip's copy of it, whose contents are checked
# apart.
# Usage: gradescope_autograder.sh BIN_DIR. Exit 0: pass, 1: fail.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "$1" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gsv-gradescope.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
start=$SECONDS
fail() { echo "gradescope_autograder: FAIL: $*" >&2; [ -s "$tmp/log" ] && { echo "--- output:" >&2; tail -n 20 "$tmp/log" >&2; }; exit 1; }
step() { echo "gradescope_autograder: [$((SECONDS - start))s] $*"; }

step "the zip"
# Where this machine refuses unshare, grade the hidden cases with the kit readable (the tests of the walls are
# elsewhere); no timing checks on this shared machine. The zip records both in run_autograder.
"$root/scripts/kit" gradescope "$tmp/autograder.zip" --labs lab01 --seed 4711 --no-timing --allow-readable-kit --include-untracked \
  >"$tmp/log" 2>&1 || fail "scripts/kit gradescope failed"
python3 - "$tmp/autograder.zip" <<'PY' || fail "the zip's contents"
import sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
names = set(z.namelist())
for top in ("setup.sh", "run_autograder"):
    assert top in names, f"no {top} at the zip's top"
    assert (z.getinfo(top).external_attr >> 16) & 0o111, f"{top} is not executable"
for needed in ("scripts/kit", "grader/cases/lab01.json", "grader/hidden/lab01.json", "CMakeLists.txt"):
    assert needed in names, f"no {needed}"
assert any(n.startswith("solutions/") for n in names), "no solutions/"
for left_out in ("slides/", "tests/", ".github/", "build/", ".git/"):
    # Of tests/, only the known mistakes the diagnosis renders (tests/mutants/<lab>.json).
    assert not any(n.startswith(left_out) and not (n.startswith("tests/mutants/") and n.endswith(".json")) for n in names), f"{left_out} is in the zip"
assert "tests/mutants/lab01.json" in names, "no known mistakes (tests/mutants/) in the zip"
PY
for bad in "--seed x" "--labs lab99" "--frobnicate" "--diagnose some"; do
  # shellcheck disable=SC2086
  if "$root/scripts/kit" gradescope "$tmp/bad.zip" $bad >"$tmp/log" 2>&1; then fail "gradescope $bad was accepted"; fi
  [ "$(wc -l <"$tmp/log")" = 1 ] || fail "gradescope $bad: not one line"
done
"$root/scripts/kit" gradescope "$tmp/autograder.zip" >"$tmp/log" 2>&1 && fail "an existing DEST was overwritten"

step "the simulated layout"
ag=$tmp/autograder
mkdir -p "$ag/source"
(cd "$ag/source" && python3 - "$tmp/autograder.zip" <<'PY'
import os, sys, zipfile
with zipfile.ZipFile(sys.argv[1]) as z:  # as unzip does: the files' modes kept
    for info in z.infolist():
        z.extract(info)
        mode = info.external_attr >> 16
        if mode:
            os.chmod(info.filename, mode & 0o777)
PY
)
ln -s "$(dirname "$bin")" "$ag/source/build"

grade_one() {  # grade_one NAME: grades what is in $ag/submission
  rm -rf "$ag/results"
  AUTOGRADER_ROOT=$ag "$ag/source/run_autograder" >"$tmp/log" 2>&1 || fail "run_autograder on the $1 exited $?"
  cp "$ag/results/results.json" "$tmp/$1.json"
}
lab_dir=$(cd "$root/solutions" && ls -d lab01_*)
step "setup.sh's references rendered ahead (its build left out: this build stands in)"
grep -qx 'scripts/kit build' "$ag/source/setup.sh" || fail "setup.sh does not build the kit"
(cd "$ag/source" && grep -vx 'scripts/kit build' setup.sh | bash) >"$tmp/log" 2>&1 || fail "setup.sh failed"
grep -q "not rendered ahead" "$tmp/log" && fail "setup.sh did not render the references ahead"
# After it, a submission's run renders none: every reference, hidden cases' included, comes from the store.
rendered_none() {
  python3 - "$ag/results/report.json" "$1" <<'PY' || fail "the $1's run rendered references setup.sh should have"
import json, sys
references = json.load(open(sys.argv[1]))["references"]
assert references.startswith("0 rendered, "), f"{sys.argv[2]}: {references}"
PY
}
step "the starter (a repository)"
mkdir -p "$ag/submission/labs"
cp -r "$root/labs/$lab_dir" "$ag/submission/labs/"
grade_one starter
rendered_none starter
step "the solution (a zip of one folder)"
rm -rf "$ag/submission"
mkdir -p "$ag/submission/my-kit/labs"
cp -r "$root/solutions/$lab_dir" "$ag/submission/my-kit/labs/"
grade_one solution
rendered_none solution

step "results.json"
python3 - "$tmp" "$root" <<'PY' || fail "results.json is not what Gradescope reads"
import base64, json, os, pathlib, subprocess, sys
tmp, root = map(pathlib.Path, sys.argv[1:])
def check(name):
    r = json.loads((tmp / f"{name}.json").read_text())
    tests = r["tests"]
    assert tests, f"{name}: no tests: {r.get('output')}"
    for t in tests:
        assert isinstance(t["name"], str) and t["name"].startswith("lab01/"), t
        assert isinstance(t["score"], (int, float)) and isinstance(t["max_score"], (int, float)), t
        assert 0 <= t["score"] <= t["max_score"], t
        assert isinstance(t["output"], str), t
    total, top = sum(t["score"] for t in tests), sum(t["max_score"] for t in tests)
    assert abs(r["score"] - total) < 1e-9, f"{name}: score {r['score']} is not the sum {total}"
    return r, total, top
solution, s_total, s_top = check("solution")
starter, t_total, t_top = check("starter")
assert s_top > 0 and s_total == s_top, f"the solution got {s_total} / {s_top}"
assert t_top == s_top and t_total < t_top / 4, f"the starter got {t_total} / {t_top}"
# The diagnosis (--diagnose public): the starter's TODOs not started, and never a hidden case's name.
assert "not started: " in starter["output"] and "L01-T1" in starter["output"], starter["output"]
assert "hidden-" not in starter["output"] and "hidden-" not in solution["output"], starter["output"]
hidden = [t for t in solution["tests"] if t.get("visibility") == "after_due_date"]
assert len(hidden) >= 3, f"{len(hidden)} hidden cases"
# GitHub Classroom points from the same results: per lab, the grader's points.
points = root / "grader" / "ci" / "classroom_points.py"
def classroom(results):
    out = subprocess.run([sys.executable, points, results, "lab01", "--cases-dir", root / "grader" / "cases"],
                         capture_output=True, text=True, env={k: v for k, v in os.environ.items() if k != "GITHUB_OUTPUT"})
    assert out.returncode == 0, out.stderr
    lab, payload = out.stdout.split(" ", 1)
    assert lab == "lab01"
    return json.loads(payload)
p = classroom(tmp / "solution.json")
assert p["status"] == "pass" and p["max_score"] == s_top and sum(t["score"] for t in p["tests"]) == s_top, p
p = classroom(tmp / "starter.json")
assert p["status"] == "fail" and sum(t["score"] for t in p["tests"]) == t_total, p
p = classroom(tmp / "missing.json")
public = sum(c.get("points", 0) for c in json.loads((root / "grader/cases/lab01.json").read_text())["cases"])
assert p["status"] == "error" and p["max_score"] == public and p["tests"][0]["score"] == 0, p
PY
step "passed"
