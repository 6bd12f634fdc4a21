#pragma once
// Lab 06's isosurface columns, the instructor's: where the rays hit against the exact Marschner-Lobb isosurface,
// and the gradient schemes (reference/volume/gradient.h, the yardstick of L06-T1) against its exact gradient.
// Compiled into lab06_solution only; the student's sweep has the images and times alone.
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

}  // namespace lab06
