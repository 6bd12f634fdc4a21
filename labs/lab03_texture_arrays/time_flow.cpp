#include "time_flow.h"

#include "common/core/error.h"
#include "common/gl/gl.h"
#include "support/flow/moving_frame.h"

#include <algorithm>

namespace lab03 {
namespace {

constexpr double kMaxSliceBytes = 1024.0 * 1024 * 1024;

int gl_limit(GLenum name) {
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}

std::vector<double> slice_times(int slices) {
    std::vector<double> times;
    for (int k = 0; k < slices; ++k) times.push_back(kPeriod * k / slices);
    return times;
}

// Of F frames spread over the period like slices, the one nearest slice k of T (at k F / T frames, rounded half
// up), past the last frame wrapped to the first (a periodic flow) or held at the last.
int nearest_frame(int k, int slices, int frames, bool repeat) {
    const long long twice = 2LL * k * frames + slices;
    const int nearest = static_cast<int>(twice / (2LL * slices));
    return repeat ? nearest % frames : std::min(nearest, frames - 1);
}

}  // namespace

gsv::FlowSequence analytic_flow_at_times(const SliceParams& p, const std::vector<double>& times) {
    const int grid = p.grid.get();
    const double speed = p.speed.get();
    return gsv::make_unsteady_flow(*p.field.get().as<gsv::UnsteadyKind>(), grid, std::max(1, grid / 2), times, speed);
}

FileFlow load_file_flow(const gsv::LabKit& kit, const SliceParams& p) {
    FileFlow file{gsv::load_flow_sequence(kit.assets().user_file(p.field_file.get())), 0.0};
    const float fastest = file.frames.max_speed();
    const double speed = p.speed.get();
    file.scale = fastest > 0 ? speed / fastest : 0.0;
    return file;
}

// The observer moves at observer_velocity times `speed` flow texels per step.
gsv::FlowSequence seen_by_observer(const SliceParams& p, gsv::FlowSequence lab_frame) {
    return gsv::seen_from_moving_frame(std::move(lab_frame), static_cast<double>(p.observer_velocity.get()) * p.speed.get());
}

gsv::FlowSequence make_time_flow(const gsv::LabKit& kit, const SliceParams& p) {
    const int slices = p.slices.get();
    if (p.field.get() != Field::File) return seen_by_observer(p, analytic_flow_at_times(p, slice_times(slices)));
    const FileFlow file = load_file_flow(kit, p);
    const int frames = static_cast<int>(file.frames.frames.size());
    gsv::FlowSequence out;
    out.width = file.frames.width;
    out.height = file.frames.height;
    for (int k = 0; k < slices; ++k) {
        gsv::FlowField frame = file.frames.frames[static_cast<std::size_t>(
            nearest_frame(k, slices, frames, p.time_wrap.get() == gsv::TimeWrap::Repeat))];
        for (float& v : frame.velocity) v = static_cast<float>(static_cast<double>(v) * file.scale);
        out.frames.push_back(std::move(frame));
    }
    return seen_by_observer(p, std::move(out));
}

void check_storage_limits(const gsv::LabKit& kit, const SliceParams& p) {
    const int slices = p.slices.get();
    const int grid = p.grid.get();
    const double bytes = 8.0 * slices * grid * std::max(1, grid / 2);
    if (p.field.get() != Field::File && bytes > kMaxSliceBytes)
        throw gsv::Error("slices=" + std::to_string(slices) + " at grid=" + std::to_string(grid) + " need " +
                         std::to_string(static_cast<long long>(bytes / (1 << 20))) + " MiB of flow; the lab allows 1024");
    const Storage storage = p.storage.get();
    if (storage == Storage::Array && slices > gl_limit(GL_MAX_ARRAY_TEXTURE_LAYERS))
        throw gsv::UnsupportedError("slices=" + std::to_string(slices) + " exceeds GL_MAX_ARRAY_TEXTURE_LAYERS = " +
                                    std::to_string(gl_limit(GL_MAX_ARRAY_TEXTURE_LAYERS)) + " on this GPU");
    if (storage == Storage::Volume && slices > gl_limit(GL_MAX_3D_TEXTURE_SIZE))
        throw gsv::UnsupportedError("slices=" + std::to_string(slices) + " exceeds GL_MAX_3D_TEXTURE_SIZE = " +
                                    std::to_string(gl_limit(GL_MAX_3D_TEXTURE_SIZE)) + " on this GPU");
    // OpenGL ES 3.0 and 3.1 (and so WebGL 2) index an array of samplers only with a constant: the lesson of
    // texture arrays, met head on.
    if (storage == Storage::Separate)
        kit.require(gsv::gl_feature::kSamplerArrayIndexing, "storage=separate (slice k is read from uFlowSlices[k])");
    // Unit 0 holds the noise.
    const int free_units = gl_limit(GL_MAX_TEXTURE_IMAGE_UNITS) - 1;
    if (storage == Storage::Separate && slices > free_units)
        throw gsv::UnsupportedError("storage=separate binds one texture unit per slice: slices=" + std::to_string(slices) +
                                    " > the " + std::to_string(free_units) +
                                    " free units (GL_MAX_TEXTURE_IMAGE_UNITS - 1); storage=array needs one");
}

}  // namespace lab03
