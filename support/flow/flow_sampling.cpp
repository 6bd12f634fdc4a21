// Shared by the analytic fields and sequences: argument checks and the one rounding from double to float.
#include "support/flow/flow_sampling.h"

#include "common/core/error.h"
#include "support/flow/flow_format.h"

#include <sstream>
#include <utility>

namespace gsv::flow_detail {

std::string fmt(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

void check_grid(const char* who, int width, int height, double max_texels_per_step) {
    for (const auto& [name, value] : {std::pair<const char*, int>{"width", width}, {"height", height}})
        if (value < 1 || value > kMaxFlowSide)
            throw Error(std::string(who) + ": " + name + " must be 1.." + std::to_string(kMaxFlowSide) + ", got " +
                        std::to_string(value));
    if (!std::isfinite(max_texels_per_step) || max_texels_per_step < 0)
        throw Error(std::string(who) + ": max_texels_per_step must be finite and >= 0, got " +
                    fmt(max_texels_per_step));
}

void check_frames(const char* who, int width, int height, int frames) {
    if (frames < 1 || frames > kMaxFlowFrames)
        throw Error(std::string(who) + ": frames must be 1.." + std::to_string(kMaxFlowFrames) + ", got " +
                    std::to_string(frames));
    const std::string too_big = flow_format::over_size_limit(frames, width, height);
    if (!too_big.empty()) throw Error(std::string(who) + ": " + too_big);
}

double DoubleField::largest_speed() const {
    double largest = 0.0;
    for (std::size_t i = 0; i < velocity.size(); i += 2)
        largest = std::max(largest, std::hypot(velocity[i], velocity[i + 1]));
    return largest;
}

FlowField DoubleField::scaled_by(double scale) const {
    FlowField field;
    field.width = width;
    field.height = height;
    field.velocity.resize(velocity.size());
    for (std::size_t i = 0; i < velocity.size(); ++i) field.velocity[i] = static_cast<float>(velocity[i] * scale);
    return field;
}

FlowField DoubleField::scaled_to(double max_texels_per_step) const {
    return scaled_by(scale_for(largest_speed(), max_texels_per_step));
}

}  // namespace gsv::flow_detail
