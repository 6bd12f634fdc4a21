#!/usr/bin/env bash
# The student's work beside the reference, live in a window (Xvfb): the starter's window steps with V through the
# reference (rendered by the kit's solution in a child process, with the window's settings), the split view and the
# difference, saving a screenshot of each (a screenshot waits for a reference still being rendered).
# Usage: window_compare_xvfb.sh STARTER_BINARY OUT_DIR
set -euo pipefail
starter=$1
out=$2
for tool in xvfb-run convert compare identify; do
  command -v $tool >/dev/null || { echo "window_compare_xvfb: $tool not installed (scripts/setup.sh installs it)"; exit 1; }
done
[ -x "$(dirname "$starter")/$(basename "$starter")_solution" ] || { echo "window_compare_xvfb: no solution beside $starter"; exit 1; }
id=$(basename "$starter")
rm -rf "$out" && mkdir -p "$out" && cd "$out"
# Frames: 2 yours (own.png), 3 V reference, 4 its screenshot, 5 V split, 6, 7 V difference, 8, then quit.
xvfb-run -a -s "-screen 0 1600x900x24" "$starter" window --size 256x256 --out own.png --press S@2 \
  --press V@3 --press S@4 --press V@5 --press S@6 --press V@7 --press S@8 --quit-after 9 > lab.log 2>&1 ||
  { cat lab.log; echo "window_compare_xvfb: the window failed"; exit 1; }
cat lab.log
fail() { echo "window_compare_xvfb: $*"; exit 1; }
differing() {  # the share of pixels that differ by more than 2%
  local count
  count=$(compare -metric AE -fuzz 2% "$1" "$2" null: 2>&1 || true)
  awk -v c="${count%% *}" -v n="$(identify -format '%[fx:w*h]' "$1")" 'BEGIN { printf "%.4f", c / n }'
}
yours=own.png reference=$id-screenshot-1.png split=$id-screenshot-2.png difference=$id-screenshot-3.png
for shot in $yours $reference $split $difference; do
  [ "$(identify -format '%wx%h' "$shot")" = 256x256 ] || fail "$shot is not 256x256"
done
grep -q 'the reference' lab.log || fail "the window did not say what its reference is"
d=$(differing $yours $reference)
echo "yours against the reference: $d of the pixels differ"
awk -v d="$d" 'BEGIN { exit !(d > 0.05) }' || fail "the starter's picture and the reference's look the same"
# Split: the left half is yours, the right half (past the divider) the reference's.
convert $yours -crop 120x256+0+0 +repage a.png; convert $split -crop 120x256+0+0 +repage b.png
[ "$(differing a.png b.png)" = 0.0000 ] || fail "the split view's left half is not yours"
convert $reference -crop 120x256+136+0 +repage a.png; convert $split -crop 120x256+136+0 +repage b.png
[ "$(differing a.png b.png)" = 0.0000 ] || fail "the split view's right half is not the reference's"
mean=$(convert $difference -colorspace Gray -format "%[fx:mean]" info:)
echo "difference view: mean grey $mean"
awk -v m="$mean" 'BEGIN { exit !(m > 0.01) }' || fail "the difference view is black where the pictures differ"
echo "compare views OK: reference, split and difference, live"
