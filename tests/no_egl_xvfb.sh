#!/usr/bin/env bash
# Headless where there is no EGL (Windows, macOS), under Xvfb: GSV_TEST_WITHOUT_EGL=1 makes this Linux build act as
# one without it (common/context/context.cpp). Each headless mode must then draw in a hidden window, say so in one line
# on stderr, and draw what EGL draws:
#  - render: the case's image equals the one rendered on EGL (no EGL override), pixel for pixel; its report names the
#    window backend;
#  - compare, with the solution beside the starter: the reference it starts draws on the same backend (started on EGL,
#    it would exit 3 and compare would fail), and yours | reference | difference is written;
#  - animate: its frames are written.
# Usage: no_egl_xvfb.sh BIN_DIR OUT_DIR
set -euo pipefail
bin=$1
out=$2
for tool in xvfb-run compare; do
  command -v $tool >/dev/null || { echo "no_egl_xvfb: $tool not installed (scripts/setup.sh installs it)"; exit 1; }
done
fail() { echo "no_egl_xvfb: $*"; exit 1; }
rm -rf "$out" && mkdir -p "$out" && cd "$out"

# On EGL first: the picture the hidden window must reproduce.
"$bin/lab01_solution" render --case phong --size 256x256 --out egl.png > egl.log 2>&1 || { cat egl.log; fail "render on EGL failed"; }

GSV_TEST_WITHOUT_EGL=1 xvfb-run -a -s "-screen 0 1280x1024x24" bash -c '
  bin=$0
  "$bin/lab01_solution" render --case phong --size 256x256 --out window.png > render.log 2>&1 || echo "render: exit $?" >> render.log
  "$bin/lab01" compare --case phong --size 256x256 --out compare.png > compare.log 2>&1 || echo "compare: exit $?" >> compare.log
  "$bin/lab03_solution" animate --count 2 --size 64x64 --out-dir anim > animate.log 2>&1 || echo "animate: exit $?" >> animate.log
' "$bin"
for log in render compare animate; do echo "--- $log"; cat $log.log; done

said="no EGL in this build (Windows, macOS): drawing headless in a hidden window"
for log in render compare animate; do
  grep -q ": exit " $log.log && fail "$log failed without EGL (its log above)"
  # Once each: compare's own run says it, the reference it starts writes its output to a log of its own.
  [ "$(grep -c "$said" $log.log)" = 1 ] || fail "$log did not say once that it draws in a hidden window"
done
grep -q '"backend": "window"' window.json || fail "render's report names no window backend: $(grep backend window.json)"
differing=$(compare -metric AE window.png egl.png null: 2>&1 || true)
[ "${differing%% *}" = 0 ] || fail "the hidden window's image differs from EGL's in ${differing%% *} pixels"
echo "render: the hidden window's phong equals EGL's, pixel for pixel"
grep -q "against lab01_solution" compare.log || fail "compare did not render its reference with lab01_solution"
[ -s compare.png ] || fail "compare wrote no compare.png"
ls anim/frame_*.png > /dev/null 2>&1 || fail "animate wrote no frames"
echo "headless without EGL OK: render, compare (its reference on the same backend) and animate in a hidden window"
