#include "support/flow/moving_frame.h"

#include "common/core/error.h"
#include "support/flow/flow_sampling.h"

#include <cmath>
#include <cstddef>
#include <utility>

namespace gsv {
namespace {

void check_velocity(double velocity_x) {
    if (!std::isfinite(velocity_x))
        throw Error("seen_from_moving_frame: the observer's velocity must be finite, got " + flow_detail::fmt(velocity_x));
}

}  // namespace

FlowField seen_from_moving_frame(FlowField field, double velocity_x) {
    check_velocity(velocity_x);
    for (std::size_t i = 0; i + 1 < field.velocity.size(); i += 2)
        field.velocity[i] = static_cast<float>(static_cast<double>(field.velocity[i]) - velocity_x);
    return field;
}

FlowSequence seen_from_moving_frame(FlowSequence sequence, double velocity_x) {
    check_velocity(velocity_x);
    for (FlowField& frame : sequence.frames) frame = seen_from_moving_frame(std::move(frame), velocity_x);
    return sequence;
}

VelocityAt seen_from_moving_frame(VelocityAt field, double velocity_x) {
    check_velocity(velocity_x);
    if (velocity_x == 0.0) return field;
    return [field = std::move(field), velocity_x](glm::dvec2 q) { return field(q) - glm::dvec2(velocity_x, 0.0); };
}

}  // namespace gsv
