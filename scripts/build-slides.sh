#!/usr/bin/env bash
# Builds the decks in slides/ into BUILD/slides/<deck>.html, offline, with pandoc's dzslides (its JavaScript
# and CSS are in pandoc's own template, and --self-contained puts every image into the page), and, where
# Chromium is installed, prints each to BUILD/slides/<deck>.pdf.
# First every figure the decks name under figures/ is made by the reference solutions and their sweeps, in
# BUILD/slides/figures: nothing in a deck is drawn by hand or committed, except the grader's golden images,
# which the solutions render too. Beside the decks, BUILD/slides/index.html lists them (the web site's "Slides" link).
# Usage: scripts/build-slides.sh [--quick] [BUILD [OUT]]   (default: build, BUILD/slides)
#   --quick   every sweep at 64x64 with one timed frame (scripts/sweeps.sh): the slides test's decks, built in
#             minutes, whose sweep figures are the real ones' shape but not numbers worth showing
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
if [ "${1:-}" = --quick ]; then
  export GSV_SWEEPS_QUICK=1
  shift
fi
case "${1:-}" in -*) echo "build-slides: unknown option '$1' (expected --quick)" >&2; exit 2 ;; esac
build="$(cd "${1:-$root/build}" && pwd)"
bin="$build/bin"
out="${2:-$build/slides}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
figures="$out/figures"

for tool in pandoc gnuplot; do
  command -v "$tool" >/dev/null || { echo "build-slides: $tool is missing (scripts/setup.sh installs it)" >&2; exit 1; }
done
# Every lab of the kit's list (scripts/kit_labs.py): its sweeps and figures are rendered by its reference.
labs=$(python3 "$root/scripts/kit_labs.py" --kit "$root" --ids) || exit 1
for lab in ${labs//,/ }; do
  [ -x "$bin/${lab}_solution" ] || { echo "build-slides: no ${lab}_solution in $bin; build first (scripts/kit build)" >&2; exit 1; }
done
rm -rf "$figures"
mkdir -p "$figures"

# Every sweep the decks show (scripts/sweeps.sh, shared with `scripts/kit tradeoffs`), and the table across the labs.
. "$root/scripts/sweeps.sh"
run_sweeps "$bin" "$figures" all
python3 "$root/scripts/tradeoffs.py" --markdown "$figures" >"$figures/tradeoffs.md"
mkdir -p "$figures/lab06-debug"
"$bin/lab06_solution" render --case probe --size 256x256 --debug-images --out "$figures/lab06-debug/probe.png" \
  >"$figures/lab06-debug.log" 2>&1 || { cat "$figures/lab06-debug.log" >&2; exit 1; }

# With Chromium there, each deck is also printed to PDF, a slide a page (deck-style.html's print rules).
chromium="$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)"
[ -n "$chromium" ] || echo "build-slides: no Chromium, so HTML only (no PDF)"

status=0
for deck in "$root"/slides/*.md; do
  name="$(basename "$deck" .md)"
  if pandoc --from markdown --to dzslides --standalone --self-contained --slide-level=2 \
       --lua-filter "$root/slides/include.lua" --include-in-header "$root/slides/deck-style.html" \
       --resource-path="$root/slides:$out" \
       --metadata pagetitle="$name" --output "$out/$name.html" "$deck"; then
    echo "build-slides: wrote $out/$name.html"
    if [ -n "$chromium" ]; then
      rm -f "$out/$name.pdf"
      timeout 120 "$chromium" --headless=new --no-sandbox --disable-gpu --no-pdf-header-footer \
        --user-data-dir="$out/.chromium" --print-to-pdf="$out/$name.pdf" "file://$out/$name.html" >/dev/null 2>&1 || true
      if [ -s "$out/$name.pdf" ]; then
        echo "build-slides: wrote $out/$name.pdf"
      else
        echo "build-slides: Chromium did not print $out/$name.pdf" >&2
        status=1
      fi
    fi
  else
    echo "build-slides: $deck did not build" >&2
    status=1
  fi
done
# The decks' index, linking each deck and the PDFs that were printed.
"$root/scripts/deck-index.sh" "$out"
echo "build-slides: wrote $out/index.html"
exit $status
