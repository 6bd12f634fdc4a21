// Time-varying flows: FlowSequence and the double gyre as a sequence. The vortex street, which only
// exists as a sequence, has its own file (vortex_street.cpp).
#include "support/flow/flow_field.h"

#include "support/flow/flow_sampling.h"

#include "common/core/enum_names.h"
#include "common/core/error.h"

#include <algorithm>
#include <cmath>

namespace gsv {

float FlowSequence::max_speed() const {
    float largest = 0.0f;
    for (const FlowField& frame : frames) largest = std::max(largest, frame.max_speed());
    return largest;
}

FlowSequence make_double_gyre_sequence(int width, int height, int frames, double max_texels_per_step) {
    // The double gyre's period is 10 (omega = 2 pi / 10): frames spread over one period loop seamlessly.
    return flow_detail::scaled_together("make_double_gyre_sequence", width, height, frames, max_texels_per_step, [&](int k) {
        return flow_detail::sample_double_gyre(width, height, 10.0 * k / frames);
    });
}

UnsteadyKind unsteady_kind_from_name(const std::string& name) {
    return parse_enum(kUnsteadyKindNames, "time-varying flow", name);
}

namespace {

flow_detail::DoubleField sample_unsteady(UnsteadyKind kind, int width, int height, double time) {
    if (kind == UnsteadyKind::DoubleGyre) return flow_detail::sample_double_gyre(width, height, time);
    const double phase = time / kUnsteadyPeriod;
    return flow_detail::sample_wide(width, height, [&](glm::dvec2 p) { return vortex_street_velocity(p, phase); });
}

}  // namespace

FlowSequence make_unsteady_flow(UnsteadyKind kind, int width, int height, const std::vector<double>& times,
                                double max_texels_per_step) {
    constexpr const char* who = "make_unsteady_flow";
    flow_detail::check_grid(who, width, height, max_texels_per_step);
    flow_detail::check_frames(who, width, height, static_cast<int>(std::min<std::size_t>(times.size(), kMaxFlowFrames + 1)));
    for (double time : times)
        if (!std::isfinite(time)) throw Error(std::string(who) + ": time " + flow_detail::fmt(time) + " is not finite");
    double largest = 0.0;
    for (int j = 0; j < kUnsteadyScaleTimes; ++j)
        largest = std::max(largest, sample_unsteady(kind, width, height, kUnsteadyPeriod * j / kUnsteadyScaleTimes).largest_speed());
    const double scale = flow_detail::scale_for(largest, max_texels_per_step);
    FlowSequence sequence;
    sequence.width = width;
    sequence.height = height;
    for (double time : times) sequence.frames.push_back(sample_unsteady(kind, width, height, time).scaled_by(scale));
    return sequence;
}

}  // namespace gsv
