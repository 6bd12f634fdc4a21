#pragma once
// Lab 06's sweep columns: where the rays hit against the exact Marschner-Lobb isosurface, and what the
// same image costs through the uber-shader and the hand-written DVR.
#include "common/app/app.h"
#include "lab_processor.h"
#include "ray_traversal.h"

namespace lab06 {

// For the Marschner-Lobb volume, isosurface compositing, no clipping plane and no probe: every
// 4th pixel's hit, read back from the ray caster's depth, against the exact crossing of rho = iso_value
// along the same ray (marschner_lobb_ray_hit, double precision; a ray entering where rho >= iso hits at its
// entry, as the module does), in model units (the signal's [-1,1]^3):
// iso_err_rms, iso_err_max, and iso_missed, the fraction of the pixels where only one of the two hits.
// With forward or central gradients also normal_err_deg: the angle between that scheme's gradient, in
// double on the volume's texels at the GPU's hit points on the isosurface (not on the box's faces, where a
// ray enters the object already inside), and the exact gradient there. Empty otherwise.
gsv::SweepMetrics measure_hits(gsv::LabKit& kit, const RayTraversal& raycaster, const FrameView& view);

// The ray caster alone, timed (glFinish and a steady clock, median of 5 after 1 warm-up) with each shader
// at the current configuration: specialised_ms, uber_ms and uber_over_specialised, and for DVR with
// central gradients, a transfer function and Phong also handwritten_ms and specialised_over_handwritten.
// The inputs are those of the network's last run.
gsv::SweepMetrics compare_shaders(RayTraversal& raycaster);

}  // namespace lab06
