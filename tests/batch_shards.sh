#!/usr/bin/env bash
# Sharded batch grading: a class graded as three shards (gsv-grade --batch --shard K/3) and merged (gsv-grade merge)
# gives the rows, per-student results and hidden cases of the same class graded in one batch; merge refuses shards
# graded with another seed, kit or labs, a shard given twice and a missing one; bad --shard values are one-line
# errors. Cheap: lab 01 only, no timing, two submissions that build (the solution and the starter), one without
# labs/ and one roster name with nothing submitted. Usage: batch_shards.sh BIN_DIR. Exit 0: pass, 1: fail.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "$1" && pwd)
grade=$bin/gsv-grade
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gsv-shards.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
start=$SECONDS
fail() { echo "batch_shards: FAIL: $*" >&2; [ -s "$tmp/log" ] && { echo "--- output:" >&2; tail -n 20 "$tmp/log" >&2; }; exit 1; }
step() { echo "batch_shards: [$((SECONDS - start))s] $*"; }

# The class: ada hands in the solution, bob the starter, cy no labs/, dee nothing (a roster name only).
lab_dir=$(cd "$root/solutions" && ls -d lab01_*)
mkdir -p "$tmp/class/ada/labs" "$tmp/class/bob/labs" "$tmp/class/cy/empty"
cp -r "$root/solutions/$lab_dir" "$tmp/class/ada/labs/"
cp -r "$root/labs/$lab_dir" "$tmp/class/bob/labs/"
printf '# the class\nada\nbob\n\ncy\ndee\n' >"$tmp/roster.txt"
# Hidden cases on (they are what the seed draws); --allow-readable-kit where unshare is refused.
common=(--no-timing --allow-readable-kit --roster "$tmp/roster.txt" --workers 2)

step "one batch"
"$grade" --batch "$tmp/class" --seed 4711 --out "$tmp/whole" --labs lab01 "${common[@]}" >"$tmp/log" 2>&1 || fail "the unsharded batch failed"
for k in 1 2 3; do
  step "shard $k/3"
  "$grade" --batch "$tmp/class" --shard "$k/3" --seed 4711 --out "$tmp/shard$k" --labs lab01 "${common[@]}" >"$tmp/log" 2>&1 \
    || fail "shard $k/3 failed"
done
[ "$("$grade" shard 2/3 "$tmp/roster.txt")" = bob ] || fail "gsv-grade shard 2/3 does not name bob"
[ "$("$grade" shard 1/3 "$tmp/roster.txt" | tr '\n' ' ')" = "ada dee " ] || fail "gsv-grade shard 1/3 does not name ada and dee"

step "merge"
"$grade" merge "$tmp/merged" "$tmp/shard3" "$tmp/shard1" "$tmp/shard2" >"$tmp/log" 2>&1 || fail "merge failed"
python3 - "$tmp/whole" "$tmp/merged" <<'PY' || fail "the merged class differs from the unsharded one"
import csv, json, pathlib, sys
whole, merged = map(pathlib.Path, sys.argv[1:])
def rows(d):  # every column but the seconds each submission took
    return [{k: v for k, v in r.items() if k != "seconds"} for r in csv.DictReader(open(d / "class.csv"))]
a, b = rows(whole), rows(merged)
assert [r["submission"] for r in a] == ["ada", "bob", "cy", "dee"], a
assert a == b, f"rows differ:\n{a}\n{b}"
assert a[0]["graded"] == "yes" and float(a[0]["score"]) == float(a[0]["max_score"]) > 0, a[0]
assert a[1]["graded"] == "yes" and float(a[1]["score"]) < float(a[1]["max_score"]), a[1]
assert a[2]["graded"] == "no" and a[3]["graded"] == "no" and "nothing submitted" in a[3]["problem"], a[2:]
assert (merged / "class.txt").read_text().count("\n") == 5
for name in ("ada", "bob", "cy"):
    def tests(d):
        r = json.loads((d / name / "results.json").read_text())
        return r["score"], [(t["name"], t["score"], t["max_score"], t.get("status"), t.get("visibility")) for t in r["tests"]]
    ta, tb = tests(whole), tests(merged)
    assert ta == tb, f"{name}: results differ\n{ta}\n{tb}"
    if name == "ada":
        hidden = [t for t in ta[1] if t[4] == "after_due_date"]
        assert len(hidden) >= 3, f"ada: {len(hidden)} hidden cases graded"
    assert (merged / name / "report.html").is_file() or name == "cy", name
assert not (merged / "dee").exists()
record = json.loads((merged / "batch.json").read_text())
assert record["shard"] == "1/1" and record["seed"] == "4711" and record["class"] == ["ada", "bob", "cy", "dee"], record
PY

# Refusals: exit 2 and one line naming the problem, nothing written.
refused() {  # refused WHAT EXPECTED_TEXT COMMAND...
  local what=$1 expected=$2
  shift 2
  local rc=0
  "$@" >"$tmp/log" 2>&1 || rc=$?
  [ "$rc" = 2 ] || fail "$what: exit status $rc, expected 2"
  [ "$(wc -l <"$tmp/log")" = 1 ] || fail "$what: not one line"
  grep -q -- "$expected" "$tmp/log" || fail "$what: no '$expected' in: $(cat "$tmp/log")"
}
step "refusals"
refused "a missing shard" "shard 3/3 missing, so are the students cy" "$grade" merge "$tmp/m1" "$tmp/shard1" "$tmp/shard2"
refused "a shard twice" "are both shard 1/3" "$grade" merge "$tmp/m2" "$tmp/shard1" "$tmp/shard1" "$tmp/shard2" "$tmp/shard3"
refused "a non-empty OUT" "must be a new or empty folder" "$grade" merge "$tmp/merged" "$tmp/shard1" "$tmp/shard2" "$tmp/shard3"
refused "not a shard" "holds no batch.json" "$grade" merge "$tmp/m3" "$tmp/class"
refused "an OUT that cannot be made" "cannot write into" "$grade" merge "$tmp/roster.txt/out" "$tmp/shard1" "$tmp/shard2" "$tmp/shard3"
[ ! -e "$tmp/m1" ] && [ ! -e "$tmp/m2" ] || fail "a refused merge wrote its OUT"
# Shard 3 (cy: no labs/, graded in a moment) again with another seed, other labs and another kit.
other_shard() {  # other_shard OUT OPTIONS...
  local out=$1
  shift
  "$grade" --batch "$tmp/class" --shard 3/3 --out "$out" "$@" >"$tmp/log" 2>&1 || fail "shard 3/3 into $out failed"
}
other_shard "$tmp/seed" --seed 4712 --labs lab01 "${common[@]}"
refused "another seed" "different seeds (4711, 4712)" "$grade" merge "$tmp/m4" "$tmp/shard1" "$tmp/shard2" "$tmp/seed"
other_shard "$tmp/labs" --seed 4711 --labs lab01,lab02 "${common[@]}"
refused "other labs" "graded different labs (lab01; lab01,lab02)" "$grade" merge "$tmp/m5" "$tmp/shard1" "$tmp/shard2" "$tmp/labs"
mkdir -p "$tmp/kit/grader"
for part in solutions shaders common support data; do ln -s "$root/$part" "$tmp/kit/$part"; done
cp -r "$root/grader/cases" "$root/grader/hidden" "$root/grader/golden" "$tmp/kit/grader/"
sed -i 's/"timeout_s": *\([0-9]*\)/"timeout_s": 1\1/' "$tmp/kit/grader/cases/lab01.json"
cmp -s "$root/grader/cases/lab01.json" "$tmp/kit/grader/cases/lab01.json" && fail "the kit copy's case file was not changed"
other_shard "$tmp/kit-out" --seed 4711 --labs lab01 "${common[@]}" --kit "$tmp/kit"
refused "another kit" "graded by different kits" "$grade" merge "$tmp/m6" "$tmp/shard1" "$tmp/shard2" "$tmp/kit-out"

for bad in 0/3 4/3 3 a/b 1/0 -1/3; do
  refused "--shard $bad" "--shard" "$grade" --batch "$tmp/class" --shard "$bad" --seed 1 --out "$tmp/bad"
done
refused "--shard without --seed" "needs --seed" "$grade" --batch "$tmp/class" --shard 1/2 --out "$tmp/bad"
refused "--shard without --batch" "needs --batch" "$grade" --shard 1/2 --seed 1
printf 'ada\n../etc\n' >"$tmp/bad-roster.txt"
refused "a roster name with a slash" "bad-roster.txt:2: '../etc'" "$grade" shard 1/2 "$tmp/bad-roster.txt"
[ ! -e "$tmp/bad" ] || fail "a refused batch wrote its --out"
step "passed"
