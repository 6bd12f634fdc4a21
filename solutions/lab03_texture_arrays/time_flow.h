#pragma once
// Lab 03's support code, not part of the lesson: the time slices to upload and the GL limits each storage runs
// into. (The sweep's measurements of what the GPU sampled are the instructor's: reference/lab03_texture_arrays/.)
#include "common/app/app.h"
#include "support/flow/flow_field.h"

#include <string>
#include <vector>

namespace lab03 {

// The period the T slices cover: flow_time.glsl's kPeriod.
inline constexpr double kPeriod = 10.0;

// The flows: support/flow's time-varying ones (gsv::kUnsteadyKindNames), then a file's.
enum class Field { File };
inline constexpr gsv::EnumName<Field> kFields[] = {{Field::File, "file"}};
using FieldChoice = gsv::OneOf<gsv::UnsteadyKind, Field>;
enum class Storage { Array, Volume, Separate };
inline constexpr gsv::EnumName<Storage> kStorages[] = {{Storage::Array, "array"}, {Storage::Volume, "volume"}, {Storage::Separate, "separate"}};

// The lab's parameters the slices are made from and held in, and their measurement reads: declared by the lab
// (lab.cpp), which keeps them.
struct SliceParams {
    gsv::EnumParam<FieldChoice> field;
    gsv::Param<std::string> field_file;
    gsv::Param<int> slices, grid;
    gsv::EnumParam<gsv::TimeBlend> blend;
    gsv::EnumParam<Storage> storage;
    gsv::EnumParam<gsv::TimeWrap> time_wrap;
    gsv::Param<float> time, speed, observer_velocity;
};

// T slices over one period, T = the `slices` parameter, slice k at time k * kPeriod / T: the analytic flows
// sampled there, or of a file's F frames (spread over the period the same way) the one nearest that time, whole:
// the slices never blend frames in time (blending is the shader's job, L03-T4), so T = F gives the file's frames
// as they are. Velocities in flow texels per step; the scale does not depend on T, so slices of any T agree
// where their times coincide. Seen by the observer: observer_velocity times `speed` taken off every x velocity.
gsv::FlowSequence make_time_flow(const gsv::LabKit& kit, const SliceParams& p);

// The pieces make_time_flow is made of, for the sweep's measurements: an analytic field (field != file) at each
// of `times` in the lab's frame; a file's frames as stored with the factor that scales its fastest texel to
// `speed`; and what the observer sees of a flow in the lab's frame.
gsv::FlowSequence analytic_flow_at_times(const SliceParams& p, const std::vector<double>& times);
struct FileFlow {
    gsv::FlowSequence frames;
    double scale = 0;
};
FileFlow load_file_flow(const gsv::LabKit& kit, const SliceParams& p);
gsv::FlowSequence seen_by_observer(const SliceParams& p, gsv::FlowSequence lab_frame);

// One line and gsv::UnsupportedError when this context cannot hold the slices in the chosen storage:
// more layers than GL_MAX_ARRAY_TEXTURE_LAYERS, a depth over GL_MAX_3D_TEXTURE_SIZE, more separate
// textures than free texture units, separate textures where a sampler array cannot be indexed by a uniform
// (OpenGL ES before 3.2); gsv::Error over 1 GiB of slices.
void check_storage_limits(const gsv::LabKit& kit, const SliceParams& p);

}  // namespace lab03
