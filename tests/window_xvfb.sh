#!/usr/bin/env bash
# Window mode under a real X server (Xvfb). The lab opens a GLFW window, draws frames with its panel and
# saves its own screenshot; an outside screenshot of the X screen (ImageMagick's import) must show it.
# Then a shader file is broken while the window runs: the lab must print the error as file:line and go
# on drawing with the last good program until it quits by itself.
# Usage: window_xvfb.sh LAB_BINARY LAB_DIR OUT_DIR   (LAB_DIR relative to the kit, e.g. solutions/lab01_gooch)
set -euo pipefail
lab=$1
lab_dir=$2
out=$3
shift 3  # the rest go to the lab (lab 05 draws fewer particles: the test is of the window, not of llvmpipe)
root=$(cd "$(dirname "$0")/.." && pwd)
for tool in xvfb-run import convert; do
  command -v $tool >/dev/null || { echo "window_xvfb: $tool not installed (scripts/setup.sh installs it)"; exit 1; }
done
rm -rf "$out" && mkdir -p "$out/kit/$(dirname "$lab_dir")"
# A private copy of the kit's files, so the test can break a shader without touching the tree.
cp -r "$root/shaders" "$root/data" "$out/kit/"
cp -r "$root/$lab_dir" "$out/kit/$lab_dir"
victim=$(ls "$out/kit/$lab_dir"/*.frag | head -1)
cd "$out"
export GSV_ROOT="$out/kit"
xvfb-run -a -s "-screen 0 800x600x24" bash -c '
  victim=$1
  shift
  "$0" window --size 640x480 --screenshot-after 10 --quit-after 10s --out own.png "$@" > lab.log 2>&1 &
  pid=$!
  for i in $(seq 1 300); do [ -s own.png ] && break; sleep 0.1; done
  sleep 0.5
  import -window root screen.png
  echo "this line is not GLSL" >> "$victim"
  for i in $(seq 1 50); do grep -q "compile error" lab.log && break; sleep 0.1; done
  kill -0 $pid || { echo "window_xvfb: the lab stopped after a broken shader edit"; exit 1; }
  wait $pid
' "$lab" "$victim" "$@"
cat lab.log
for shot in own.png screen.png; do
  [ -s "$shot" ] || { echo "window_xvfb: no $shot"; exit 1; }
  deviation=$(convert "$shot" -colorspace Gray -format "%[fx:standard_deviation]" info:)
  echo "$shot: grey standard deviation $deviation"
  awk -v d="$deviation" 'BEGIN { exit !(d > 0.02) }' || { echo "window_xvfb: $shot is blank"; exit 1; }
done
grep -q "OpenGL" lab.log || { echo "window_xvfb: the lab did not report its context"; exit 1; }
grep -q "$(basename "$victim"):[0-9]*: error" lab.log || { echo "window_xvfb: no file:line error after the broken edit"; exit 1; }
echo "window mode OK: drew, took screenshots, survived a broken shader edit"
