#!/usr/bin/env bash
# Window mode under a real X server (Xvfb): the lab opens a GLFW window, draws frames with its panel,
# saves its own screenshot, and an outside screenshot of the X screen (ImageMagick's import) shows the
# window. Both must be non-blank. Usage: window_xvfb.sh LAB_BINARY OUT_DIR
set -euo pipefail
lab=$1
out=$2
rm -rf "$out" && mkdir -p "$out"
for tool in xvfb-run import convert; do
  command -v $tool >/dev/null || { echo "window_xvfb: $tool not installed (scripts/setup.sh installs it)"; exit 1; }
done
cd "$out"
xvfb-run -a -s "-screen 0 800x600x24" bash -c '
  "$0" window --size 640x480 --screenshot-after 10 --quit-after 400 --out own.png > lab.log 2>&1 &
  pid=$!
  for i in $(seq 1 200); do [ -s own.png ] && break; sleep 0.1; done
  sleep 0.5
  import -window root screen.png
  wait $pid
' "$lab"
cat lab.log
for shot in own.png screen.png; do
  [ -s "$shot" ] || { echo "window_xvfb: no $shot"; exit 1; }
  deviation=$(convert "$shot" -colorspace Gray -format "%[fx:standard_deviation]" info:)
  echo "$shot: grey standard deviation $deviation"
  awk -v d="$deviation" 'BEGIN { exit !(d > 0.02) }' || { echo "window_xvfb: $shot is blank"; exit 1; }
done
grep -q "llvmpipe\|OpenGL" lab.log || { echo "window_xvfb: the lab did not report its context"; exit 1; }
echo "window mode OK"
