#!/usr/bin/env bash
# The gl41 kind's windows (README, "Kinds of test"): every public case of every lab's solution drawn in a window
# (render --backend window: a hidden GLFW window, what macOS's headless modes use) on OpenGL 4.1 core, macOS's ceiling,
# by Mesa's version override, under Xvfb, and judged against its golden by gsv-golden-judge (the grader's comparator
# under the case's golden tolerance, as the self-check judges). Lab 05 draws its L05-T2 cases too: at 4.1 they step by
# transform feedback, and their pictures are the compute path's.
# Usage: gl41_window_goldens.sh KIT_ROOT BIN_DIR OUT_DIR
set -euo pipefail
root=$(cd "$1" && pwd)
bin=$(cd "$2" && pwd)
out=$3
command -v xvfb-run >/dev/null || { echo "gl41_window_goldens: skipped: no xvfb-run (xvfb)"; exit 77; }
rm -rf "$out"
mkdir -p "$out"
judge=$bin/gsv-golden-judge
IFS=, read -r -a labs <<<"$(python3 "$root/scripts/kit_labs.py" --kit "$root" --ids)"
start=$(date +%s)
cat >"$out/session.sh" <<'SCRIPT'
set -uo pipefail
out=$1 bin=$2 judge=$3 root=$4
shift 4
export MESA_GL_VERSION_OVERRIDE=4.1 MESA_GLSL_VERSION_OVERRIDE=410
for lab in "$@"; do
  mkdir -p "$out/$lab"
  while read -r name size; do
    (cd "$root" && "$bin/${lab}_solution" render --backend window --case "$name" --size "$size" --frames 1 --warmup 0 \
      --out "$out/$lab/$name.png") </dev/null >"$out/$lab/$name.log" 2>&1 ||
      echo "$lab/$name: render failed: $(tail -1 "$out/$lab/$name.log")"
  done < <("$judge" "$root" "$lab" --sizes)
done
SCRIPT
xvfb-run -a -s "-screen 0 1280x800x24" bash "$out/session.sh" "$out" "$bin" "$judge" "$root" "${labs[@]}" </dev/null
failed=0
for lab in "${labs[@]}"; do
  # Each render says the context it drew on: 4.1 core, in a window.
  for log in "$out/$lab"/*.log; do
    grep -q "OpenGL 4.1 (Core Profile)" "$log" ||
      { echo "gl41_window_goldens: $lab/$(basename "$log" .log) did not draw on OpenGL 4.1 core:"; cat "$log"; failed=1; }
  done
  if "$judge" "$root" "$lab" "$out/$lab" >"$out/$lab/judged.txt"; then tail -1 "$out/$lab/judged.txt"
  else grep -v ": passed:" "$out/$lab/judged.txt"; failed=1; fi
done
[ $failed = 0 ] || { echo "gl41_window_goldens: a public case drawn in a window at OpenGL 4.1 does not match its golden"; exit 1; }
echo "gl41_window_goldens: every public case of every lab drawn in a window at OpenGL 4.1 core matches its golden; $(( $(date +%s) - start )) s"
