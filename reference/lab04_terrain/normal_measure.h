#pragma once
// Lab 04's sweep columns, the instructor's: the shader's normals against exact and double-precision ones
// (reference/terrain/terrain_normal.h, the yardstick of L04-T1 and L04-T2). Compiled into lab04_solution only; the
// student's sweep has the images alone. Its sweep plan (sweep_plan.cpp) calls it.
#include "common/app/app.h"
#include "common/gl/gpu_mesh.h"
#include "terrain_source.h"

#include <functional>

namespace lab04 {

// The shader's normals (normal_probe.frag, one fragment per sample) against the exact normals of a
// procedural terrain or, for a real model, the normals of its full-resolution differences (delta 1): mean and
// largest angle in degrees; and the largest angle between the shader's normals and the same differences in
// double precision at the same delta (finite_difference_normal for a whole step), which only rounding should
// separate, until a step far below a sample makes float32 cancel.
gsv::SweepMetrics measure_normals(gsv::LabKit& kit, const Terrain& terrain, const gsv::ShaderLibrary::Entry& probe,
                                  const gsv::GpuMesh& quad, const std::function<void(const gsv::ShaderProgram&)>& set_uniforms);

}  // namespace lab04
