# The sweeps the decks show and `scripts/kit tradeoffs` tabulates, in one place (sourced by build-slides.sh and
# kit). Small and quick: the decks show the shape of each trade-off; the lab sheets hold the full-size tables.
#   run_sweeps BIN_DIR OUT_DIR primary   each lab's own accuracy knob, one sweep per lab: OUT_DIR/labXX
#   run_sweeps BIN_DIR OUT_DIR all       those and the decks' other sweeps (lab05-rotation, lab06-shaders, ...)
# Which sweeps, with which options: each lab's lab.json ("sweeps"), read through scripts/kit_labs.py.
# A failing sweep prints its log and exits the caller.

# GSV_SWEEPS_QUICK=1 (the slides test's): every sweep at 64x64, one timed frame and no warm-up, after the sweep's own
# options (the last --size wins): the same figures and tables from the same code, their numbers not worth reading.
sweep_one() {  # sweep_one BIN_DIR OUT_DIR NAME LAB [options...]
  local bin="$1" dir="$2/$3" lab="$4"
  shift 4
  local quick=()
  [ "${GSV_SWEEPS_QUICK:-0}" = 1 ] && quick=(--size 64x64 --frames 1 --warmup 0)
  echo "sweep: $(basename "$dir")" >&2
  mkdir -p "$dir"
  "$bin/$lab" sweep --size 192x192 --frames 3 --warmup 1 --out-dir "$dir" "$@" ${quick[@]+"${quick[@]}"} >"$dir.log" 2>&1 ||
    { cat "$dir.log" >&2; exit 1; }
}

run_sweeps() {  # run_sweeps BIN_DIR OUT_DIR primary|all
  # Each lab's sweeps are in its lab.json (cmake/lab_list.cmake): the one named after the lab is its accuracy sweep
  # (no options where it names none), those named <lab>-... its deck's.
  local bin="$1" out="$2" which="$3" plan name lab options
  local kit
  kit=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  plan=$(python3 "$kit/scripts/kit_labs.py" --kit "$kit" --sweeps "$which") || exit 1
  # The plan on its own descriptor: a sweep's process must not read the rest of it from its standard input.
  while read -r name lab options <&3; do
    # shellcheck disable=SC2086  # an option holds no space (kit_labs.py writes them one word each)
    sweep_one "$bin" "$out" "$name" "${lab}_solution" $options
  done 3<<<"$plan"
}
