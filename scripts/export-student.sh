#!/usr/bin/env bash
# Exports the student edition of the kit into DEST: everything a student needs to do the labs and self-check
# them against the committed golden images, and nothing that gives answers away.
#
#   scripts/export-student.sh [--include-untracked] [--labs lab01,lab02] DEST   (also: scripts/kit export-student ...)
#
# --labs releases only those labs (their labs/ folder, case file, golden images and golden arrays); a course
# that hands labs out week by week exports again as each opens. Later labs give earlier answers away (lab 03's
# shaders trace lab 02's LIC streamlines): --labs refuses a lab without the labs whose answers its starter holds,
# as the table "Answers a later lab holds" in labs/README.md declares them.
# Left out: solutions/, reference/ (the instructor's CPU yardsticks, which answer TODOs), tests/ (they need the
# solutions), grader/hidden/ (hidden grading cases), .github/ (the instructor's workflows), build*/ folders,
# grade-results/, .git, and whatever git ignores. In a git checkout
# only the files git tracks are exported (their working-tree content); --include-untracked adds the untracked
# files that git does not ignore. Outside git, every file is copied but those excluded above and those matching
# the kit's top-level .gitignore (simple patterns only).
# Replaced or added in DEST: .ci/run (the student self-check), .github/workflows/self-check.yml (from
# grader/ci/github-classroom.yml), and README.md, the student edition's own (its two commands work there). The lab
# sheets lose what points at the reference or the tests; the slides keep the figures the edition ships (the golden
# images) and name the ones only the reference renders.
# DEST must not exist or be an empty folder, and must be outside the kit.
set -euo pipefail

die() { echo "export-student: $*" >&2; exit 1; }
usage() { echo "usage: scripts/export-student.sh [--include-untracked] [--labs lab01,lab02] DEST" >&2; exit 2; }

include_untracked=0
release_labs=""
dest=""
while [ $# -gt 0 ]; do
  case "$1" in
    --include-untracked) include_untracked=1 ;;
    --labs) [ $# -ge 2 ] || usage; release_labs=$2; shift ;;
    -h|--help) sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "export-student: unknown option '$1'" >&2; usage ;;
    *) [ -z "$dest" ] || usage; dest=$1 ;;
  esac
  shift
done
[ -n "$dest" ] || usage

root=$(cd "$(dirname "$0")/.." && pwd -P)

# The canonical absolute form of a path that need not exist yet.
abs_path() {
  local p=$1 rest=""
  case "$p" in /*) ;; *) p="$PWD/$p" ;; esac
  while [ ! -d "$p" ]; do
    case "$(basename "$p")" in .|..) die "cannot resolve '$1': give DEST without . or .. past the existing part" ;; esac
    rest="/$(basename "$p")$rest"
    p=$(dirname "$p")
  done
  p=$(cd "$p" && pwd -P)
  echo "${p%/}$rest"
}

if [ -e "$dest" ] || [ -L "$dest" ]; then
  [ -d "$dest" ] || die "'$dest' exists and is not a folder"
  [ -z "$(ls -A "$dest")" ] || die "'$dest' is not empty; give a new or empty folder"
fi
dest_abs=$(abs_path "$dest")
case "$dest_abs/" in
  "$root/"*) die "'$dest' is inside the kit ($root); export to a folder outside it" ;;
esac
[ -f "$root/grader/ci/github-classroom.yml" ] || die "grader/ci/github-classroom.yml is missing from the kit"

# The labs not released (--labs): their folders, case files and golden images stay behind.
withheld=()
if [ -n "$release_labs" ]; then
  # The kit's labs are its folders solutions/labNN_name/ (cmake/lab_list.cmake), read here without CMake: the export
  # needs no set-up.
  known=""
  for folder in "$root"/solutions/lab[0-9][0-9]_*/; do
    [ -d "$folder" ] || continue
    dir=$(basename "$folder")
    known+=" ${dir:0:5}:$dir"
  done
  [ -n "$known" ] || die "no lab folders (solutions/labNN_name/) in $root"
  IFS=, read -r -a wanted <<<"$release_labs"
  for lab in "${wanted[@]}"; do
    case " $known " in *" $lab:"*) ;; *) die "--labs: unknown lab '$lab' (the kit has: $(echo "$known" | sed 's/:[^ ]*//g'))" ;; esac
  done
  for entry in $known; do
    lab=${entry%%:*} dir=${entry#*:}
    case ",$release_labs," in *",$lab,"*) continue ;; esac
    withheld+=("labs/$dir/" "grader/cases/$lab.json" "grader/golden/$lab/")
  done
fi

# A later lab's starter that holds an earlier lab's answers (labs/README.md, "Answers a later lab holds": rows
# | later | earlier | `files` | ... |) goes out only with that earlier lab.
held_answers() {
  [ -f "$root/labs/README.md" ] || return 0
  sed -n 's/^| *\(lab[0-9][0-9]\) *| *\(lab[0-9][0-9]\) *| *\([^|]*[^ |]\) *|.*/\1 \2 \3/p' "$root/labs/README.md" | tr -d '`'
}
if [ -n "$release_labs" ]; then
  while read -r later earlier files; do
    case ",$release_labs," in *",$later,"*) ;; *) continue ;; esac
    case ",$release_labs," in *",$earlier,"*) continue ;; esac
    die "--labs: ${later}'s starter holds ${earlier}'s answers (${files}): release $earlier too, after its deadline"
  done < <(held_answers)
elif [ -n "$(held_answers)" ]; then
  echo "export-student: every lab goes out, and later labs' starters hold earlier labs' answers (labs/README.md," \
       "\"Answers a later lab holds\"); release week by week with --labs" >&2
fi

# What never goes to students, whichever way the file list is made.
excluded() {
  local w
  for w in ${withheld[@]+"${withheld[@]}"}; do
    case "$1" in "$w"*) return 0 ;; esac
  done
  case "$1" in
    solutions|solutions/*|reference|reference/*|tests|tests/*|grader/hidden|grader/hidden/*|.github/*) return 0 ;;
    build*/*|*/build*/*) return 0 ;;
    grade-results/*|*/grade-results/*) return 0 ;;
    .git|.git/*|*/.git|*/.git/*) return 0 ;;
  esac
  return 1
}

# Without git: the kit's top-level .gitignore, read the simple way (no negation, no **).
gitignore_patterns=()
if [ -f "$root/.gitignore" ]; then
  while IFS= read -r line || [ -n "$line" ]; do
    line=${line%$'\r'}
    case "$line" in ''|'#'*|'!'*) continue ;; esac
    gitignore_patterns+=("$line")
  done <"$root/.gitignore"
fi
ignored() {
  local path=$1 pat dir_only anchored prefix comp
  local -a comps
  IFS=/ read -r -a comps <<<"$path"
  for pat in ${gitignore_patterns[@]+"${gitignore_patterns[@]}"}; do
    dir_only=0; anchored=0
    case "$pat" in */) dir_only=1; pat=${pat%/} ;; esac
    case "$pat" in /*) anchored=1; pat=${pat#/} ;; */*) anchored=1 ;; esac
    prefix=""
    local i n=${#comps[@]}
    for ((i = 0; i < n; i++)); do
      comp=${comps[i]}
      prefix=${prefix:+$prefix/}$comp
      # A directory-only pattern matches the folders on the path, not the file itself.
      if [ $dir_only -eq 1 ] && [ $i -eq $((n - 1)) ]; then break; fi
      if [ $anchored -eq 1 ]; then
        # shellcheck disable=SC2053
        [[ $prefix == $pat ]] && return 0
      else
        # shellcheck disable=SC2053
        [[ $comp == $pat ]] && return 0
      fi
    done
  done
  return 1
}

list=$(mktemp)
trap 'rm -f "$list"' EXIT
count=0
skipped_untracked=0
add() {  # a path relative to the kit root
  excluded "$1" && return 0
  [ -f "$root/$1" ] || [ -L "$root/$1" ] || return 0  # deleted in the working tree, or a submodule folder
  printf '%s\0' "$1" >>"$list"
  count=$((count + 1))
}

if command -v git >/dev/null 2>&1 && git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  source_kind="git checkout"
  while IFS= read -r -d '' f; do add "$f"; done < <(git -C "$root" ls-files -z --cached)
  if [ $include_untracked -eq 1 ]; then
    while IFS= read -r -d '' f; do add "$f"; done < <(git -C "$root" ls-files -z --others --exclude-standard)
  else
    while IFS= read -r -d '' f; do
      excluded "$f" || skipped_untracked=$((skipped_untracked + 1))
    done < <(git -C "$root" ls-files -z --others --exclude-standard)
  fi
else
  source_kind="folder (no git)"
  while IFS= read -r -d '' f; do
    f=${f#./}
    ignored "$f" || add "$f"
  done < <(cd "$root" && find . \( -name .git -o -path ./solutions -o -path ./reference -o -path ./tests -o -path ./grader/hidden \
                                   -o -path ./.github -o -name 'build*' -type d -o -name grade-results \) -prune \
                                -o \( -type f -o -type l \) -print0)
fi
[ $count -gt 0 ] || die "no files to export from $root"

mkdir -p "$dest_abs"
(cd "$root" && tar --null -T "$list" -cf -) | (cd "$dest_abs" && tar -xf -)

# The student edition's own files.
mkdir -p "$dest_abs/.ci" "$dest_abs/.github/workflows"
cat >"$dest_abs/.ci/run" <<'EOF'
#!/usr/bin/env bash
# CI of the student edition: a fresh Debian/Ubuntu machine, no GPU. Installs what the kit needs (scripts/setup.sh),
# builds, and self-checks labs/ against the committed golden images. The reports land in build/grade-results.
# Exits 0 whenever grading ran, whatever the score; pass --fail-under F (0..1) to fail below a fraction of the points.
set -euo pipefail
cd "$(dirname "$0")/.."
export DEBIAN_FRONTEND=noninteractive
exec scripts/kit grade --self-check "$@"
EOF
chmod 755 "$dest_abs/.ci/run"
cp "$root/grader/ci/github-classroom.yml" "$dest_abs/.github/workflows/self-check.yml"

# Its own README, whose two commands work here (the instructor's README names tests and solutions it lacks).
cat >"$dest_abs/README.md" <<'EOF'
# GPU Shaders for Visualization: student edition

The framework, the labs' starter code, the slides, and the grading cases with their golden images. The reference
solutions, the test suite and the hidden grading cases stay with your instructor.

## Quick start (Debian 12 / Ubuntu; two commands)

```sh
scripts/kit grade                  # install what is missing, build, self-check every lab against the golden images
scripts/kit grade --todo L01-T3    # build one lab and self-check one TODO's cases (the ids are in each lab sheet)
```

`scripts/kit grade --labs lab02` self-checks one lab. On macOS and Windows, `scripts/setup.sh` prints the Homebrew
and vcpkg equivalents; then `cmake --preset default && cmake --build --preset default`. On Windows without a
compiler, the labs also come as a zip your instructor makes (`scripts/kit windows` on Debian): unpacked anywhere,
`lab01.exe` runs the lab, `lab01.exe compare --case phong` checks a case against its golden image, and your shaders
are in its `gsv-assets\labs\` (its `README.txt` says more). Or do the labs in the browser edition, with nothing to
install.

## Your work

- Edit the files in `labs/<lab>/` (for example `labs/lab01_gooch/`). Each TODO has an id such as `L01-T3`; the lab
  sheet, `labs/<lab>/README.md`, explains it and names its grading cases. Only `labs/` is graded: the instructor's
  grader builds your `labs/` against its own copy of the framework, shaders and data, so changes anywhere else are
  not seen.
- `build/bin/lab01` opens your lab in a window (shaders reload when saved; H lists the keys); `build/bin/lab01 list`
  shows its parameters and named cases; `build/bin/lab01 render --case phong --out phong.png` renders one headless.
- `build/bin/lab01 compare --case phong` writes `lab01-compare-phong.png`: your render, the case's golden image and
  their difference, amplified, side by side, and prints the RMSE and the largest difference; where your picture is
  one of the kit's known mistakes, that mistake's picture is a fourth view and a line says what went wrong. In labs 04 to 07,
  `render --legend` adds a colour bar with the values the colours stand for, sampled from your own shaders.

## Self-check

The self-check renders each public case of `grader/cases/<lab>.json` with your lab and compares the image with the
committed golden image in `grader/golden/<lab>/`, rendered by the reference solution, with a tolerance wide enough
for another GPU or driver. It prints a score table: each failing case says what is wrong (not done, which TODO it
needs first, a compile error in your file, a wrong image) and the command that reproduces it. It opens with what went
wrong: your failing pictures compared with the pictures of mistakes students often make (`grader/golden/<lab>/mistakes.*`),
naming the idea missed, its TODO and the part of the sheet that teaches it, or saying that no known mistake matches;
where you have not started, the TODO to start with (one whose case needs no other). It writes
`build/grade-results/`: `report.html` (your image, the expected one and where they differ, as small thumbnails),
`results.json` and `junit.xml`. Every push runs the same check on GitHub (`.github/workflows/self-check.yml`, also
`.ci/run`).

## What the instructor's grade adds

- **Hidden cases**, drawn from a seed kept secret until after the due date: other settings (models, scales, camera,
  resolutions, ...) for the same TODOs. Solve each TODO in general, not for the public cases.
- **A live reference**: the reference solution renders each case on the grading machine, and your image must match
  it with a tight tolerance.
- **Timing**: cases whose frame time is compared with the reference's, measured by the grader's own clock.
- Each build and run of your code is sandboxed: it sees only your lab and the kit's public files.

So a full self-check score is a good sign, not a guarantee; a case that fails the self-check will almost surely fail
the grade too.

## Where things are

`labs/` your code; `common/` the framework and `support/` the labs' shared domain code (read them, don't change them:
the grader uses its own); `shaders/` shared GLSL; `data/` meshes and data sets (sources in `data/README.md`);
`grader/` the grader, the public cases and the golden images; `slides/` a deck per lab (Markdown); `CONTRIBUTING.md`
the kit's conventions for names and GLSL.
EOF

# The lab sheets as a student reads them: nothing that points at the reference or the test suite. The instructor's
# rows (where the answers, tests and sweep plan are) are a section of their own, "## For the instructor", left out
# whole, from its heading to the next section of the same level or the end.
for sheet in "$dest_abs"/labs/*/README.md; do
  [ -f "$sheet" ] || continue
  awk '/^## For the instructor$/ { skip = 1; next } skip && /^##? / { skip = 0 } skip { next }
       /^$/ { blank++; next } { for (; blank > 0; blank--) print ""; print }' "$sheet" >"$sheet.tmp" &&
    mv "$sheet.tmp" "$sheet"
  sed -i -e 's/ and `build\/bin\/\(lab[0-9]*\)_solution` for the reference//' \
         -e 's/\(lab[0-9][0-9]\)_solution/\1/g' \
         -e 's/`*tests\/test_[a-z0-9_]*\.cpp`*\(, `*tests\/test_[a-z0-9_]*\.cpp`*\)*/the kit'"'"'s tests/g' \
         "$sheet"
done

# The decks: a figure the edition ships stays; one that only the reference solutions render is named instead.
if command -v python3 >/dev/null 2>&1; then
  python3 - "$dest_abs" <<'PY'
import os, re, sys
root = sys.argv[1]
figure = re.compile(r"!\[([^\]]*)\]\(([^)\s]+)\)(\{[^}]*\})?")
for name in sorted(os.listdir(os.path.join(root, "slides"))):
    if not name.endswith(".md"):
        continue
    path = os.path.join(root, "slides", name)
    text = open(path, encoding="utf-8").read()
    def keep(m):
        target = os.path.normpath(os.path.join(root, "slides", m.group(2)))
        if os.path.exists(target):
            return m.group(0)
        return f"*({m.group(1) or 'figure'}: rendered by the reference solution, in the instructor's edition)*"
    open(path, "w", encoding="utf-8").write(figure.sub(keep, text))
PY
fi

total=$(cd "$dest_abs" && find . -type f | wc -l | tr -d ' ')
if [ $skipped_untracked -gt 0 ]; then
  echo "export-student: left out $skipped_untracked untracked file(s) (git status shows them; --include-untracked adds them)" >&2
fi
echo "exported the student edition of $root ($source_kind): $total files in $dest_abs;" \
     "self-check: cd $dest_abs && scripts/kit grade"
