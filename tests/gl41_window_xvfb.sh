#!/usr/bin/env bash
# A lab's window on macOS's OpenGL 4.1 core profile (Mesa's version override), under Xvfb: window_xvfb.sh's checks
# (panel, screenshots, a broken shader edit survived), and the lab's log saying it ran on a 4.1 core context.
# Usage: gl41_window_xvfb.sh LAB_BINARY LAB_DIR OUT_DIR [lab options]
set -euo pipefail
out=$3
MESA_GL_VERSION_OVERRIDE=4.1 MESA_GLSL_VERSION_OVERRIDE=410 "$(dirname "$0")/window_xvfb.sh" "$@"
grep -q "OpenGL 4.1 (Core Profile).*core profile, window backend" "$out/lab.log" ||
  { echo "gl41_window_xvfb: the lab's log does not say it ran on an OpenGL 4.1 core context"; exit 1; }
echo "gl41_window_xvfb: the window ran on OpenGL 4.1 core: $(grep -m1 'OpenGL 4.1' "$out/lab.log")"
