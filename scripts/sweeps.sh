# The sweeps the decks show and `scripts/kit tradeoffs` tabulates, in one place (sourced by build-slides.sh and
# kit). Small and quick: the decks show the shape of each trade-off; the lab sheets hold the full-size tables.
#   run_sweeps BIN_DIR OUT_DIR primary   each lab's own accuracy knob, one sweep per lab: OUT_DIR/labXX
#   run_sweeps BIN_DIR OUT_DIR all       those and the decks' other sweeps (lab05-rotation, lab06-shaders, ...)
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
  local bin="$1" out="$2" which="$3"
  sweep_one "$bin" "$out" lab01 lab01_solution
  sweep_one "$bin" "$out" lab02 lab02_solution --knob length --values 1,5,25,100
  sweep_one "$bin" "$out" lab03 lab03_solution
  # Franke's terrain: its exact normals are known, so its error is against the truth.
  sweep_one "$bin" "$out" lab04 lab04_solution --set terrain=franke
  sweep_one "$bin" "$out" lab05 lab05_solution --set particles=65536
  sweep_one "$bin" "$out" lab06 lab06_solution --set compositing=iso
  sweep_one "$bin" "$out" lab07 lab07_solution
  [ "$which" = all ] || return 0
  sweep_one "$bin" "$out" lab04-jacksboro lab04_solution --set terrain=jacksboro
  # Precision: float32 cancellation at tiny steps, and heights rounded to 8 bits, against Franke's exact normals.
  sweep_one "$bin" "$out" lab04-tiny-steps lab04_solution --set terrain=franke --set grid=512 --knob delta \
    --values 0.00001,0.0001,0.01,1
  sweep_one "$bin" "$out" lab04-heights8 lab04_solution --set terrain=franke --knob heights8 --values on,off
  # Real geometry against the bump-mapped quad, at a grazing view, against one vertex per sample (343).
  sweep_one "$bin" "$out" lab04-mesh lab04_solution --set terrain=jacksboro --set geometry=mesh --set camera_pitch=10 \
    --set camera_distance=2.2 --knob mesh_n --values 2,8,32,128,343
  # The closed-form radii after one turn of the rotation (round(6.3 / h) steps is a turn to within h / 2).
  sweep_one "$bin" "$out" lab05-rotation lab05_solution --set particles=65536 --set field=rotation --set time=6.3
  # The seed's Figure 11, small: particles per second against the work-group size, GPU and CPU.
  sweep_one "$bin" "$out" lab05-local-size lab05_solution --size 128x128 --set field=gravity --set integrator=euler \
    --set particles=262144 --set time=0.1 --knob local_size --values 1,8,64,128,1024
  sweep_one "$bin" "$out" lab06-shaders lab06_solution --size 256x256 --knob samples_per_voxel --values 0.5,1,2 \
    --set compare_shaders=on --set compositing=dvr
  sweep_one "$bin" "$out" lab06-shaders-mip lab06_solution --size 256x256 --knob samples_per_voxel --values 0.5,1 \
    --set compare_shaders=on --set compositing=mip
  sweep_one "$bin" "$out" lab06-dvr lab06_solution --set compositing=dvr
  # The isosurface's floor is the reconstruction from 41 samples a side: twice as many a side lowers it.
  sweep_one "$bin" "$out" lab06-iso81 lab06_solution --set compositing=iso --set ml_size=81
  sweep_one "$bin" "$out" lab07-runge lab07_solution --set mesh=grid --set columns=1 --set rows=1 --set field=runge
}
