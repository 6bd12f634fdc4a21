#!/usr/bin/env bash
# Window mode under a real X server (Xvfb). The lab opens a GLFW window, draws frames with its panel and saves its
# own screenshots (the picture, and the whole window); an outside screenshot of the X screen (ImageMagick's import)
# must show it. Keys are pressed by the lab's --press:
#  - the panel is docked beside the picture: at least 70% of the picture's pixels show uncovered in the window;
#  - U hides the panel: the picture then fills the window;
#  - with --inspect (lab 06), I steps through the network's port images: each non-blank, each different.
# Then a shader file is broken while the window runs: the lab must print the error as file:line and go on drawing
# with the last good program until it quits by itself.
# Usage: window_xvfb.sh LAB_BINARY LAB_DIR OUT_DIR [--inspect] [lab options]   (LAB_DIR relative to the kit)
set -euo pipefail
lab=$1
lab_dir=$2
out=$3
shift 3
inspect=0
if [ "${1:-}" = --inspect ]; then inspect=1; shift; fi
# The rest go to the lab (lab 05 draws fewer particles: the test is of the window, not of llvmpipe).
root=$(cd "$(dirname "$0")/.." && pwd)
for tool in xvfb-run import convert compare identify; do
  command -v $tool >/dev/null || { echo "window_xvfb: $tool not installed (scripts/setup.sh installs it)"; exit 1; }
done
id=$(basename "$lab" | sed 's/_solution$//')
rm -rf "$out" && mkdir -p "$out/kit/$(dirname "$lab_dir")"
# A private copy of the kit's files, so the test can break a shader without touching the tree.
cp -r "$root/shaders" "$root/data" "$out/kit/"
cp -r "$root/$lab_dir" "$out/kit/$lab_dir"
# The victim: the first fragment shader the lab's own C++ loads (a shader only its sweep plan draws with, in reference/,
# is never built by the window).
victim=""
for frag in "$out/kit/$lab_dir"/*.frag; do
  grep -qF "\"$(basename "$frag")\"" "$out/kit/$lab_dir"/*.cpp && { victim=$frag; break; }
done
[ -n "$victim" ] || { echo "window_xvfb: no fragment shader of $lab_dir is named in its C++ to break"; exit 1; }
cd "$out"
export GSV_ROOT="$out/kit"
# Frames: 3 the picture with its panel (own.png), 5 hide, 7 the picture alone (screenshot-1), 8 show again,
# 10 the last screenshot (screenshot-2); with --inspect, three port images at 12, 14 and 16.
# The script ends the lab once it has survived the broken edit; --quit-after is a safety net.
presses=(--press S@3 --press U@5 --press S@7 --press U@8 --quit-after 120s)
last=2
if [ $inspect -eq 1 ]; then
  presses+=(--press I@11 --press S@12 --press I@13 --press S@14 --press I@15 --press S@16)
  last=5
fi
xvfb-run -a -s "-screen 0 1600x900x24" bash -c '
  victim=$1
  wait_for=$2
  shift 2
  "$0" window --screenshot-after 10 --out own.png "$@" > lab.log 2>&1 &
  pid=$!
  for i in $(seq 1 600); do [ -s "$wait_for" ] && break; sleep 0.1; done
  sleep 0.5
  import -window root screen.png
  echo "this line is not GLSL" >> "$victim"
  for i in $(seq 1 150); do grep -q "compile error" lab.log && break; sleep 0.1; done
  sleep 1  # frames drawn with the last good program
  kill -0 $pid || { echo "window_xvfb: the lab stopped after a broken shader edit"; exit 1; }
  # Ended here rather than by a wall time, which a loaded machine reaches before the edit (the lab flushes its output
  # every frame; --quit-after only ends a lab this script has lost).
  kill $pid
  wait $pid || true
' "$lab" "$victim" "$id-screenshot-$last.png" "${presses[@]}" "$@"
cat lab.log
fail() { echo "window_xvfb: $*"; exit 1; }
non_blank() {
  [ -s "$1" ] || fail "no $1"
  local deviation
  deviation=$(convert "$1" -colorspace Gray -format "%[fx:standard_deviation]" info:)
  echo "$1: grey standard deviation $deviation"
  awk -v d="$deviation" 'BEGIN { exit !(d > 0.02) }' || fail "$1 is blank"
}
differing() {  # differing A B: the share of pixels that differ by more than 2%
  local count
  count=$(compare -metric AE -fuzz 2% "$1" "$2" null: 2>&1 || true)
  awk -v c="${count%% *}" -v n="$(identify -format '%[fx:w*h]' "$1")" 'BEGIN { printf "%.4f", c / n }'
}
size() { identify -format '%wx%h' "$1"; }
for shot in own.png own-window.png screen.png "$id-screenshot-1.png"; do non_blank "$shot"; done

# At the default size, docked: the window is wider than the picture, and its left part is the picture, uncovered.
[ "$(size own.png)" = 512x512 ] || fail "own.png is $(size own.png), not the default 512x512"
window_w=$(identify -format '%w' own-window.png)
[ "$window_w" -gt 512 ] || fail "the window ($(size own-window.png)) has no room for the panel beside the picture"
convert own-window.png -crop 512x512+0+0 +repage picture-in-window.png
covered=$(differing own.png picture-in-window.png)
echo "panel shown: window $(size own-window.png), picture 512x512, share of the picture covered: $covered"
awk -v c="$covered" 'BEGIN { exit !(c <= 0.30) }' || fail "the panel covers $covered of the picture (at most 0.30)"

# U hid the panel: the picture fills the window.
hidden="$id-screenshot-1"
[ "$(size "$hidden.png")" = "$(size "$hidden-window.png")" ] || fail "with the panel hidden the picture is $(size "$hidden.png"), the window $(size "$hidden-window.png")"
[ "$(identify -format '%w' "$hidden.png")" = "$window_w" ] || fail "with the panel hidden the picture is not as wide as the window"
echo "panel hidden: the picture fills the window, $(size "$hidden.png")"

if [ $inspect -eq 1 ]; then
  for k in 3 4 5; do non_blank "$id-screenshot-$k.png"; done
  for pair in "3 4" "4 5" "3 5"; do
    set -- $pair
    d=$(differing "$id-screenshot-$1.png" "$id-screenshot-$2.png")
    echo "inspector: port images $1 and $2 differ in $d of their pixels"
    awk -v d="$d" 'BEGIN { exit !(d > 0.01) }' || fail "port images $1 and $2 are the same picture"
  done
  grep -c '^inspecting ' lab.log | grep -q '^3$' || fail "the lab did not report three inspected images"
fi
grep -q "OpenGL" lab.log || fail "the lab did not report its context"
grep -q "$(basename "$victim"):[0-9]*: error" lab.log || fail "no file:line error after the broken edit"
echo "window mode OK: docked panel, hide key, screenshots, survived a broken shader edit"
