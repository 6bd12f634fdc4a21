#pragma once
// Lab 03's sweep columns, the instructor's: what the GPU sampled at the playhead against the CPU's mix of the same
// slices in double (reference/flow/time_slices.h, the yardstick of L03-T2 and L03-T4), and the temporal error of
// T slices against the flow itself, for its sweep plan (sweep_plan.cpp). Compiled into lab03_solution only.
#include "common/app/app.h"
#include "common/gl/gpu_mesh.h"
#include "support/flow/flow_field.h"
#include "time_flow.h"

#include <functional>

namespace lab03 {

// The largest difference between the flow the GPU sampled at the playhead and the CPU's (double precision) mix of
// the same slices ("sample err": exactly 0 for an array; a 3D texture's filter shows here); the temporal error of
// T slices against the flow itself (analytic, or a file's frames blended linearly in time), RMS over 37 playheads
// of the period; and the slices' memory.
gsv::SweepMetrics measure_sampling(gsv::LabKit& kit, const SliceParams& params, const gsv::ShaderLibrary::Entry& probe,
                                   const gsv::GpuMesh& quad, const gsv::FlowSequence& flow,
                                   const std::function<void(const gsv::ShaderProgram&)>& bind_flow);

}  // namespace lab03
