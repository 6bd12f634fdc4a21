#!/usr/bin/env bash
# The slides test: builds every deck (scripts/build-slides.sh) and opens each in headless Chromium
# (check_slides.py). Exit 77, which ctest reports as skipped, naming what is missing, where a tool is not
# installed: students need no browser, and the test should say it did not run rather than vanish.
# Usage: check_slides.sh KIT_ROOT BUILD_DIR
set -euo pipefail
root=$1
build=$2
missing=()
for tool in pandoc gnuplot python3; do command -v "$tool" >/dev/null || missing+=("$tool"); done
command -v chromium >/dev/null || command -v chromium-browser >/dev/null || command -v google-chrome >/dev/null ||
  missing+=(chromium)
if [ ${#missing[@]} -gt 0 ]; then
  echo "slides_build_and_open: skipped, ${missing[*]} not installed (apt-get install ${missing[*]}; .ci/run installs them)"
  exit 77
fi
# Quick sweeps (64x64, one frame: the figures' code, not numbers to read) into their own folder, so that the decks a
# lecturer built with scripts/kit slides in build/slides are left as they are.
"$root/scripts/build-slides.sh" --quick "$build" "$build/slides-test"
python3 "$root/tests/check_slides.py" "$root/slides" "$build/slides-test"
