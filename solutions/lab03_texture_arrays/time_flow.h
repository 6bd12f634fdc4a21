#pragma once
// Lab 03's support code, not part of the lesson: the time slices to upload, the GL limits each
// storage runs into, and the sweep's measurements of what the GPU sampled.
#include "common/app/app.h"
#include "common/gl/gpu_mesh.h"
#include "support/flow/flow_field.h"

#include <functional>
#include <string>

namespace lab03 {

// T slices over one period, T = the `slices` parameter, slice k at time k * 10 / T: the analytic flows
// sampled there, or a file's F frames (spread over the period the same way) blended linearly in time.
// Velocities in flow texels per step; the scale does not depend on T, so slices of any T agree where
// their times coincide. Seen by the observer: observer_velocity times `speed` taken off every x velocity.
gsv::FlowSequence make_time_flow(gsv::LabKit& kit);

// One line and gsv::UnsupportedError when this context cannot hold the slices in the chosen storage:
// more layers than GL_MAX_ARRAY_TEXTURE_LAYERS, a depth over GL_MAX_3D_TEXTURE_SIZE, more separate
// textures than free texture units, separate textures where a sampler array cannot be indexed by a uniform
// (OpenGL ES before 3.2); gsv::Error over 1 GiB of slices.
void check_storage_limits(const gsv::LabKit& kit);

// The sweep's columns: the largest difference between the flow the GPU sampled at the playhead and the
// CPU's (double precision) mix of the same slices ("sample err": exactly 0 for an array; a 3D
// texture's filter shows here); the temporal error of T slices against the flow itself (analytic, or a
// file's frames blended linearly), RMS over 37 playheads of the period; and the slices' memory.
gsv::SweepMetrics measure_sampling(gsv::LabKit& kit, const gsv::ShaderLibrary::Entry& probe, const gsv::GpuMesh& quad,
                                   const gsv::FlowSequence& flow,
                                   const std::function<void(const gsv::ShaderProgram&)>& bind_flow);

}  // namespace lab03
