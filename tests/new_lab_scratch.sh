#!/usr/bin/env bash
# A lab added by `scripts/kit new-lab` (labs/README.md, "Adding a lab"), in a scratch copy of the kit:
#   - new-lab writes only the lab's own files (solutions/lab99_probe/, grader/cases/lab99.json, slides/99-probe.md),
#     and its starter and goldens, made by the kit's tools, only the lab's own and the tools' manifests;
#   - configure works before the starter exists, and says what to run;
#   - it builds (only its two targets: the framework comes from ccache, compiled by the kit's own build), and its
#     starter renders magenta where the reference does not;
#   - it is in every list taken from the folders: the build's (labs.json), the tests' (its window and softpipe tests,
#     and each per-lab Catch test of the kit's test binary read against the scratch list), the CI templates' (the
#     Classroom points), the sweeps' and tradeoffs', the benchmarks', the web edition's (its pages, where Emscripten
#     is here) and the margin table's (check-lab measures it);
#   - check-lab passes its starter, goldens, self-check both ways and margins, and names the rules it still misses:
#     too few cases, no hidden cases, no known or held-out mistakes.
# Usage: new_lab_scratch.sh KIT BUILD GSV_TESTS   (BUILD: the kit's build, whose tools and test binary are used)
set -euo pipefail
root=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
tests_bin=$3
start=$(date +%s)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gsv-new-lab.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
kit=$tmp/kit
log=$tmp/log
step() { echo "new_lab: $*  ($(( $(date +%s) - start )) s)"; }
fail() { echo "new_lab: FAIL: $*"; [ -f "$log" ] && tail -40 "$log"; exit 1; }

step "a scratch copy of the kit (its files but data/)"
python3 - "$root" "$kit" <<'PY'
import os, shutil, subprocess, sys
root, kit = sys.argv[1:3]
listed = subprocess.run(["git", "-C", root, "ls-files", "-z", "-co", "--exclude-standard"], capture_output=True)
if listed.returncode == 0:
    files = [f for f in listed.stdout.decode().split("\0") if f]
else:  # not a git checkout: every file but the build folders
    files = [os.path.relpath(os.path.join(d, f), root) for d, _, fs in os.walk(root) for f in fs]
for rel in files:
    top = rel.split("/")[0]
    if top.startswith("build") or top in ("data", ".git") or "node_modules/" in rel:
        continue
    source = os.path.join(root, rel)
    if os.path.isfile(source):
        os.makedirs(os.path.dirname(os.path.join(kit, rel)), exist_ok=True)
        shutil.copy2(source, os.path.join(kit, rel))
# data/'s folders, empty: the web edition makes a package of each.
for name in os.listdir(os.path.join(root, "data")):
    if os.path.isdir(os.path.join(root, "data", name)):
        os.makedirs(os.path.join(kit, "data", name), exist_ok=True)
PY
manifest() { (cd "$kit" && find . -path ./build -prune -o -type f -print0 | sort -z | xargs -0 sha1sum) >"$1"; }
changed() {  # changed BEFORE AFTER: the paths added, changed or removed
  python3 - "$1" "$2" <<'PY'
import sys
def read(p): return {l[42:].strip()[2:]: l[:40] for l in open(p)}
a, b = read(sys.argv[1]), read(sys.argv[2])
print("\n".join(sorted(p for p in set(a) | set(b) if a.get(p) != b.get(p))))
PY
}
manifest "$tmp/before"

step "scripts/kit new-lab 99 probe"
"$kit/scripts/kit" new-lab 99 probe "A probe lab" >"$log" 2>&1 || fail "new-lab failed"
grep -q "scripts/kit check-lab lab99" "$log" || fail "new-lab does not say what to run next"
manifest "$tmp/after"
touched=$(changed "$tmp/before" "$tmp/after")
echo "$touched" | sed 's/^/  /'
outside=$(echo "$touched" | grep -vE '^(solutions/lab99_probe/|grader/cases/lab99\.json$|slides/99-probe\.md$)' || true)
[ -z "$outside" ] || fail "new-lab touched files outside the lab's own: $outside"
"$kit/scripts/kit" new-lab 99 again >"$log" 2>&1 && fail "a second lab99 was not refused"
grep -q "lab99 is taken" "$log" || fail "a second lab99 is refused without saying why"

step "configure before the starter exists: it works, and says what to run"
(cd "$kit" && cmake --preset default -DGSV_WERROR=ON) >"$log" 2>&1 || fail "configure failed without the starter"
grep -q "lab99: no starter yet" "$log" && grep -q "scripts/kit starters" "$log" || fail "configure does not say to generate the starter"

step "its starter and goldens, by the kit's tools"
"$build/bin/gsv-make-starters" --write --root "$kit" >"$log" 2>&1 || fail "gsv-make-starters --write failed"
[ -f "$kit/labs/lab99_probe/shade.frag" ] || fail "no starter in labs/lab99_probe/"
step "it builds: lab99 and lab99_solution only"
cmake --build "$kit/build" --target lab99 lab99_solution >"$log" 2>&1 || fail "lab99 does not build"
bin=$kit/build/bin
"$build/bin/gsv-grade" --kit "$kit" --bin "$bin" --update-goldens --labs lab99 --quiet --out "$tmp/goldens" >"$log" 2>&1 ||
  fail "gsv-grade --update-goldens --labs lab99 failed"
[ -f "$kit/grader/golden/lab99/stripes.png" ] || fail "no golden grader/golden/lab99/stripes.png"
manifest "$tmp/made"
made=$(changed "$tmp/after" "$tmp/made")
outside=$(echo "$made" | grep -vE '^(labs/lab99_probe/|grader/golden/lab99/)' |
          grep -vxE 'grader/starters\.json|grader/golden/renderer\.json' || true)
[ -z "$outside" ] || fail "the starter and goldens touched files outside the lab's own and the tools' manifests: $outside"

step "the starter is magenta, the reference is not"
"$bin/lab99" render --case stripes --size 32x32 --out "$tmp/starter.png" >"$log" 2>&1 || fail "the starter does not render"
"$bin/lab99_solution" render --case stripes --size 32x32 --out "$tmp/solution.png" >"$log" 2>&1 || fail "the reference does not render"
python3 - "$tmp/starter.png" "$tmp/solution.png" <<'PY' || fail "the starter is not all magenta, or the reference is"
import struct, sys, zlib
def pixels(path):  # 8-bit RGB or RGBA PNG, every filter
    data = open(path, "rb").read()
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            channels = {2: 3, 6: 4}[colour]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b, c = prev[x], prev[x - channels] if x >= channels else 0
            p = a + b - c
            pred = [0, a, b, (a + b) // 2, a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else (b if abs(p - b) <= abs(p - c) else c)][f]
            line[x] = (line[x] + pred) & 255
        rows.append(line)
        prev = line
    return [tuple(r[x * channels:x * channels + 3]) for r in rows for x in range(width)]
starter, solution = pixels(sys.argv[1]), pixels(sys.argv[2])
assert all(p == (255, 0, 255) for p in starter), set(starter)
assert not any(p == (255, 0, 255) for p in solution), set(solution)
PY

step "in every list taken from the folders"
grep -q '"id" : "lab99"' "$kit/build/labs.json" || fail "not in the build's list (build/labs.json)"
ctest --test-dir "$kit/build" -N >"$log" 2>&1 || fail "ctest -N failed"
grep -q "lab99_window_under_xvfb" "$log" && grep -q "lab99_graded_on_softpipe" "$log" || fail "no window or softpipe test of lab99"
# (Catch 2's exit status is the number of tests listed.)
GSV_LAB_LIST=$kit/build/labs.json "$tests_bin" --list-test-names-only >"$log" 2>&1 || true
for name in "lab99: every TODO left undone" "lab99: every seed's hidden cases" "lab99: each case passes with its TODO" \
            "lab99: two mistakes in two TODOs" "lab99: the solution scores full marks" "es: lab99 graded on its lowest"; do
  grep -q "^$name" "$log" || fail "the tests made for each lab have no '$name...'"
done
: >"$tmp/output"
GITHUB_OUTPUT=$tmp/output GITHUB_ENV=$tmp/env python3 "$kit/grader/ci/classroom_points.py" "$tmp/none.json" \
  --cases-dir "$kit/grader/cases" >"$log" 2>&1 || fail "classroom_points.py failed"
grep -q "^runners=.*lab99" "$tmp/output" && grep -q "^LAB99_RESULTS=" "$tmp/env" || fail "no Classroom points for lab99"
python3 "$kit/scripts/kit_labs.py" --kit "$kit" --sweeps all >"$log" 2>&1 || fail "kit_labs.py --sweeps failed"
grep -qx "lab99 lab99" "$log" || fail "no sweep of lab99 (scripts/sweeps.sh)"
"$bin/lab99_solution" sweep --size 32x32 --frames 1 --warmup 0 --out-dir "$tmp/sweeps/lab99" >"$log" 2>&1 || fail "lab99's sweep failed"
python3 "$kit/scripts/tradeoffs.py" "$tmp/sweeps" >"$log" 2>&1 && fail "tradeoffs passed without the other labs' sweeps"
grep -q "lab01/lab01-summary.csv" "$log" && ! grep -q "lab99/lab99-summary.csv" "$log" || fail "tradeoffs does not take lab99's sweep"
python3 -c "import sys; sys.path.insert(0, sys.argv[1]); import bench_class; assert bench_class.LABS['lab99'] == 'lab99_probe'" \
  "$kit/scripts" || fail "not in the class benchmark's labs (scripts/bench_class.py)"
python3 "$kit/scripts/kit_labs.py" --kit "$kit" --ids >"$log" 2>&1 || fail "kit_labs.py --ids failed"
grep -q "lab99" "$log" || fail "not in the web benchmark's and pages' labs (scripts/bench_web.js, tests/web/check_pages.js)"
if command -v em++ >/dev/null && [ -f /usr/share/emscripten/cmake/Modules/Platform/Emscripten.cmake ] &&
   [ -d "$root/web/node_modules/jszip" ] && [ -d /usr/share/javascript/codemirror ]; then
  ln -s "$root/web/node_modules" "$kit/web/node_modules"
  (cd "$kit" && cmake --preset web -B "$kit/build-web" >"$log" 2>&1) || fail "the web edition does not configure with lab99"
  [ -f "$kit/build-web/site/lab99/index.html" ] || fail "the web edition has no page for lab99"
else
  step "  (no Emscripten or web/node_modules: the web edition's list is cmake/labs.cmake's, as the build's above)"
fi

step "check-lab lab99: its steps pass, and it names what the lab still lacks"
python3 "$kit/scripts/check_lab.py" lab99 --kit "$kit" --bin "$bin" --tools "$build/bin" >"$log" 2>&1 &&
  fail "check-lab passed a lab with one case"
cat "$log" | sed 's/^/  /'
grep -q "^1. starters: labs/lab99_probe/ is what" "$log" || fail "check-lab: the starter"
grep -q "^2. goldens: every public case has its golden" "$log" || fail "check-lab: the goldens"
grep -q "^3. self-check: the reference 1 / 1" "$log" && grep -q "the starter 0 / 1" "$log" || fail "check-lab: the self-check"
grep -qE "^4. margins: (every case meets the bar|no implementation)" "$log" || fail "check-lab: the margins"
for rule in public_cases hidden_cases mistakes_per_todo mistake_pairs held_out_mistakes; do
  grep -q "misses the rule '$rule'" "$log" || fail "check-lab does not name the rule $rule"
done
grep -qE "misses the rule '(goldens|margins)'" "$log" && fail "check-lab names a rule the lab meets"
step "passed in $(( $(date +%s) - start )) s"
