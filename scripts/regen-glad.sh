#!/usr/bin/env bash
# Regenerates the committed GL and GL ES loader (one merged set of entry points: gladLoadGL for desktop
# contexts, gladLoadGLES2 for ES) in third_party/glad with glad 2 (Debian: python3-glad).
# --reproducible uses the Khronos XML bundled with glad, so the output depends only on glad's version.
# Usage: scripts/regen-glad.sh [OUT_DIR]   (default: third_party/glad; the drift test passes a temp dir)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/third_party/glad}
command -v glad >/dev/null || { echo "regen-glad: 'glad' not found (apt-get install python3-glad)" >&2; exit 2; }
glad --quiet --reproducible --api gl:compatibility=4.5,gles2=3.2 --extensions "" --merge --out-path "$out" c
