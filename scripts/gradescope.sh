#!/usr/bin/env bash
# The Gradescope autograder: scripts/kit gradescope DEST.zip writes a zip whose top holds Gradescope's setup.sh and
# run_autograder beside the kit, with the solutions and hidden cases (it grades) and without what only students or
# kit developers use (slides/, tests/, .github/, build folders, earlier results). Gradescope unpacks it into
# /autograder/source, runs setup.sh once when it builds the image (the kit's packages and build: scripts/kit build)
# and run_autograder for each submission, which grades /autograder/submission into /autograder/results/results.json.
#
#   scripts/kit gradescope DEST.zip [--seed N] [--labs lab01,lab02] [--timing] [--allow-readable-kit]
#                                   [--diagnose off|public|all] [--include-untracked]
#
# --seed N     the seed of the hidden cases, baked into the zip (one seed for the whole class); default: a fresh one,
#              printed. The zip then holds it: share it as you would the hidden cases.
# --labs       grade only these labs (a Gradescope assignment per lab); default: every lab with a case file.
# --timing     add the frame-time checks. Off by default: Gradescope's machines are shared, so a frame time there says
#              as much about the neighbours as about the student (a grade must depend on the sources alone), and they
#              cost a run about 70% more (grader/README.md, "Gradescope"). --no-timing, the default, is accepted.
# --allow-readable-kit  where Gradescope's container refuses unshare, grade the hidden cases anyway with the kit
#              readable by student code (see "Where the walls cannot go up" in grader/README.md); without it such
#              a container gives every submission a results.json saying it could not be graded, and why.
# --diagnose   which failing cases are compared with the kit's known mistakes (tests/mutants/, packed into the zip)
#              to tell the student the mistake they made: public (default: never a hidden case), off (exams) or all.
# --include-untracked   in a git checkout, also the untracked files git does not ignore (default: tracked only).
set -euo pipefail
die() { echo "gradescope: $*" >&2; exit 2; }
usage() { die "usage: scripts/kit gradescope DEST.zip [--seed N] [--labs lab01,lab02] [--timing] [--allow-readable-kit] [--diagnose off|public|all] [--include-untracked]"; }
root=$(cd "$(dirname "$0")/.." && pwd)

dest="" seed="" labs="" readable=0 include_untracked=0 timing=0 diagnose=public
while [ $# -gt 0 ]; do
  case "$1" in
    --seed) [ $# -ge 2 ] || usage; seed=$2; shift 2 ;;
    --labs) [ $# -ge 2 ] || usage; labs=$2; shift 2 ;;
    --allow-readable-kit) readable=1; shift ;;
    --timing) timing=1; shift ;;
    --no-timing) timing=0; shift ;;
    --diagnose) [ $# -ge 2 ] || usage; diagnose=$2; shift 2
      case "$diagnose" in off|public|all) ;; *) die "--diagnose takes off, public or all, got '$diagnose'" ;; esac ;;
    --include-untracked) include_untracked=1; shift ;;
    -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
    -*) die "unknown option '$1' (see --help)" ;;
    *) [ -z "$dest" ] || usage; dest=$1; shift ;;
  esac
done
[ -n "$dest" ] || usage
case "$dest" in *.zip) ;; *) die "DEST must end in .zip, got '$dest'" ;; esac
[ ! -e "$dest" ] || die "'$dest' exists: give a new file"
dest_dir=$(cd "$(dirname "$dest")" 2>/dev/null && pwd) || die "no folder '$(dirname "$dest")' for '$dest'"
dest_abs=$dest_dir/$(basename "$dest")
[ -d "$root/solutions" ] && [ -d "$root/grader/hidden" ] || die "$root has no solutions/ or grader/hidden/: the autograder is made from the instructor's kit"
case "$seed" in *[!0-9]*) die "--seed needs a whole number, got '$seed'" ;; esac
if [ -n "$labs" ]; then
  IFS=, read -r -a wanted <<<"$labs"
  for lab in "${wanted[@]}"; do
    [ -f "$root/grader/cases/$lab.json" ] || die "--labs: no case file grader/cases/$lab.json for '$lab'"
  done
fi
command -v python3 >/dev/null || die "python3 is needed to write the zip"
if [ -z "$seed" ]; then
  seed=$(( ($(od -An -N4 -tu4 /dev/urandom | tr -d ' ') % 900000000) + 100000000 ))
  echo "gradescope: drew the seed $seed (baked into the zip)"
fi

# The file list: what git tracks (or every file outside git), less what the autograder has no use for. Of tests/ it
# keeps the known mistakes (tests/mutants/), which the diagnosis renders; the zip is the instructor's, never a student's.
excluded() {
  case "$1" in
    tests/mutants/*.json) return 1 ;;
    slides/*|tests/*|.github/*|build*/*|grade-results/*|sweep-*/*|.git/*|*/.git/*) return 0 ;;
  esac
  return 1
}
list=$(mktemp)
stage=$(mktemp -d)
trap 'rm -rf "$list" "$stage"' EXIT
if command -v git >/dev/null 2>&1 && git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  { git -C "$root" ls-files -z --cached
    [ $include_untracked -eq 0 ] || git -C "$root" ls-files -z --others --exclude-standard; } >"$list.all"
else
  (cd "$root" && find . \( -name .git -o -name 'build*' -type d -o -name grade-results \) -prune -o -type f -printf '%P\0') >"$list.all"
fi
while IFS= read -r -d '' f; do
  excluded "$f" || { [ -f "$root/$f" ] && printf '%s\0' "$f"; }
done <"$list.all" >"$list"
rm -f "$list.all"
[ -s "$list" ] || die "no files to pack from $root"
mkdir -p "$stage/kit"
(cd "$root" && tar --null -T "$list" -cf -) | (cd "$stage/kit" && tar -xf -)

options="--seed $seed"
[ -z "$labs" ] || options="$options --labs $labs"
[ $readable -eq 0 ] || options="$options --allow-readable-kit"
[ $timing -eq 1 ] || options="$options --no-timing"
options="$options --diagnose $diagnose"
# Gradescope reads results.json only: a passed case's pictures as a thumbnail, no binaries kept (grader/README.md).
options="$options --passed-pictures thumbnail --keep-build no"
cat >"$stage/kit/setup.sh" <<EOF2
#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image: the kit's Debian/Ubuntu packages
# (scripts/setup.sh) and its build with the reference solutions. Written by scripts/kit gradescope.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
cd "\$(dirname "\$0")"
scripts/kit build
# Every case's reference (the hidden cases' of the baked seed too) and the known mistakes' pictures the diagnosis
# shows, rendered once here into build/grader-cache/references with the binaries, driver and seed of every run: a
# submission's run then renders only the student's work. The kit's own labs/ are the starters, which fail every
# case, so the diagnosis renders every public case's mistakes. Each entry is checked against its key in every run.
if ! build/bin/gsv-grade $options --quiet --out /tmp/gsv-references-ahead; then
  echo "setup.sh: the references were not rendered ahead (above): each submission's run renders its own" >&2
fi
rm -rf /tmp/gsv-references-ahead
EOF2
cat >"$stage/kit/run_autograder" <<EOF2
#!/usr/bin/env bash
# Gradescope runs this for each submission: /autograder/submission holds the student's files (their repository,
# or a zip with labs/ at its top or in its one folder), /autograder/results/results.json is what Gradescope reads.
# AUTOGRADER_ROOT stands in for /autograder where the layout is simulated. Written by scripts/kit gradescope.
set -uo pipefail
top=\${AUTOGRADER_ROOT:-/autograder}
kit=\$top/source
submission=\$top/submission
# A zip of one folder that holds labs/: grade that folder.
if [ ! -d "\$submission/labs" ]; then
  inner=\$(find "\$submission" -mindepth 2 -maxdepth 2 -type d -name labs -print -quit)
  [ -z "\$inner" ] || submission=\$(dirname "\$inner")
fi
mkdir -p "\$top/results"
cd "\$kit"
# The kit and binaries gsv-grade was built with and for: on Gradescope this folder and its build/.
"\$kit/build/bin/gsv-grade" --submission "\$submission" --out "\$top/results" \\
  $options
status=\$?
# gsv-grade writes results.json whenever it graded or could name why not; anything else still gets one.
if [ ! -s "\$top/results/results.json" ]; then
  printf '{"score": 0, "output": "The autograder failed (exit status %d): tell your instructor.", "tests": []}\n' "\$status" \\
    >"\$top/results/results.json"
fi
exit \$status
EOF2
chmod 755 "$stage/kit/setup.sh" "$stage/kit/run_autograder"

# Python's zipfile keeps each file's mode (run_autograder and the kit's scripts stay executable after unzip).
python3 - "$stage/kit" "$dest_abs" <<'PY'
import os, sys, zipfile
src, dest = sys.argv[1:]
with zipfile.ZipFile(dest, "w", zipfile.ZIP_DEFLATED) as z:
    for folder, dirs, files in os.walk(src):
        dirs.sort()
        for name in sorted(files):
            path = os.path.join(folder, name)
            z.write(path, os.path.relpath(path, src))
PY
echo "gradescope: wrote $dest_abs ($(python3 -c 'import sys, zipfile; print(len(zipfile.ZipFile(sys.argv[1]).namelist()))' "$dest_abs") files, $(du -h "$dest_abs" | cut -f1)): upload it as the autograder; seed $seed${labs:+, labs $labs}"
