#!/usr/bin/env bash
# Builds the decks in slides/ into BUILD/slides/<deck>.html, offline, with pandoc's dzslides (its JavaScript
# and CSS are in pandoc's own template, and --self-contained puts every image into the page), and, where
# Chromium is installed, prints each to BUILD/slides/<deck>.pdf.
# First every figure the decks name under figures/ is made by the reference solutions and their sweeps, in
# BUILD/slides/figures: nothing in a deck is drawn by hand or committed, except the grader's golden images,
# which the solutions render too. Usage: scripts/build-slides.sh [BUILD]   (default: build)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
bin="$build/bin"
out="$build/slides"
figures="$out/figures"

for tool in pandoc gnuplot; do
  command -v "$tool" >/dev/null || { echo "build-slides: $tool is missing (scripts/setup.sh installs it)" >&2; exit 1; }
done
[ -x "$bin/lab07_solution" ] || { echo "build-slides: no lab binaries in $bin; build first (scripts/kit build)" >&2; exit 1; }
rm -rf "$figures"
mkdir -p "$figures"

# Small and quick: the decks show the shape of each trade-off; the lab sheets hold the full-size tables.
sweep() {  # sweep <figure dir> <lab binary> [options...]
  local dir="$figures/$1" lab="$2"
  shift 2
  echo "build-slides: figures/$(basename "$dir")"
  "$bin/$lab" sweep --size 192x192 --frames 3 --warmup 1 --out-dir "$dir" "$@" >"$dir.log" 2>&1 ||
    { cat "$dir.log" >&2; exit 1; }
}
sweep lab01 lab01_solution
sweep lab02 lab02_solution --knob length --values 1,5,25,100
sweep lab03 lab03_solution
sweep lab04 lab04_solution
sweep lab05 lab05_solution --set particles=65536
sweep lab06 lab06_solution --set compositing=iso
sweep lab06-shaders lab06_solution --size 256x256 --knob samples_per_voxel --values 1,2 --set compare_shaders=on \
  --set compositing=dvr
sweep lab07 lab07_solution
sweep lab07-runge lab07_solution --set mesh=grid --set columns=1 --set rows=1 --set field=runge
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
exit $status
