#pragma once
// Internal to the flow sources (flow_field.cpp, flow_sequence.cpp, vortex_street.cpp): how an analytic
// field becomes a grid of texel velocities. Kept out of flow_field.h so labs see only finished fields.
#include "support/flow/flow_field.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace gsv::flow_detail {

// Shortest-readable form for messages: std::to_string would print 1e-9 as 0.000000.
std::string fmt(double value);

// Throws gsv::Error "<who>: ..." unless both sides are 1..kMaxFlowSide and max_texels_per_step is finite and >= 0.
void check_grid(const char* who, int width, int height, double max_texels_per_step);

// Throws gsv::Error "<who>: ..." unless frames is 1..kMaxFlowFrames and the sequence would fit in a .flow
// file, so that whatever is generated can also be saved.
void check_frames(const char* who, int width, int height, int frames);

// A field being built: velocities in texels per step, in double until the final scaling so that the
// rounding to float happens once.
struct DoubleField {
    int width, height;
    std::vector<double> velocity;

    DoubleField(int w, int h) : width(w), height(h), velocity(2 * static_cast<std::size_t>(w) * h, 0.0) {}

    // Calls velocity_at(x, y) with texel indices and stores what it returns.
    template <typename VelocityAt>
    void fill(VelocityAt velocity_at) {
        std::size_t i = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const glm::dvec2 v = velocity_at(x, y);
                velocity[i++] = v.x;
                velocity[i++] = v.y;
            }
    }

    double largest_speed() const;
    // Every velocity times `scale`, rounded to float once.
    FlowField scaled_by(double scale) const;
    // Scaled so the largest speed is max_texels_per_step; a zero field is left zero, not divided by 0.
    FlowField scaled_to(double max_texels_per_step) const;
};

// The factor that takes `largest` to max_texels_per_step; 0 for a zero field rather than a division by 0.
inline double scale_for(double largest, double max_texels_per_step) {
    return largest > 0.0 ? max_texels_per_step / largest : 0.0;
}

// frames sampled by sample_frame(k) (a DoubleField), all scaled by the one factor that makes the largest
// speed over the whole sequence max_texels_per_step. Each frame is sampled twice, once to find that
// speed and once to scale it, so no more than one frame is ever held in double. The grid and frame count are
// checked first (check_grid, check_frames), naming `who`.
template <typename SampleFrame>
FlowSequence scaled_together(const char* who, int width, int height, int frames, double max_texels_per_step,
                             SampleFrame sample_frame) {
    check_grid(who, width, height, max_texels_per_step);
    check_frames(who, width, height, frames);
    double largest = 0.0;
    for (int k = 0; k < frames; ++k) largest = std::max(largest, sample_frame(k).largest_speed());
    const double scale = scale_for(largest, max_texels_per_step);
    FlowSequence sequence;
    sequence.width = width;
    sequence.height = height;
    sequence.frames.reserve(static_cast<std::size_t>(frames));
    for (int k = 0; k < frames; ++k) sequence.frames.push_back(sample_frame(k).scaled_by(scale));
    return sequence;
}

// A point in texel coordinates (texel (i, j)'s centre at (i + 0.5, j + 0.5)) on the domain [-1,1]^2. Written as
// (2q - n) / n so that at a texel centre the numerator 2i + 1 - n is an exact integer: texels i and n-1-i land
// on exactly opposite points, and the middle texel of an odd n on exactly 0.
inline glm::dvec2 square_domain_point(glm::dvec2 q, int width, int height) {
    return {(2.0 * q.x - width) / width, (2.0 * q.y - height) / height};
}

// The same on [0,2]x[0,1] (the double gyre, the vortex street): 2 domain units across width texels, 1 unit up
// height texels.
inline glm::dvec2 wide_domain_point(glm::dvec2 q, int width, int height) {
    return {2.0 * q.x / width, 2.0 * q.y / (2.0 * height)};
}

// An analytic field on [-1,1]^2 as a field in texels at any point in texel coordinates, unscaled: one domain
// unit spans n/2 texels along each axis.
template <typename Analytic>
auto square_in_texels(int width, int height, Analytic analytic) {
    return [width, height, analytic](glm::dvec2 q) {
        const glm::dvec2 v = analytic(square_domain_point(q, width, height));
        return glm::dvec2(v.x * 0.5 * width, v.y * 0.5 * height);
    };
}

// An analytic field on [0,2]x[0,1] the same way.
template <typename Analytic>
auto wide_in_texels(int width, int height, Analytic analytic) {
    return [width, height, analytic](glm::dvec2 q) {
        const glm::dvec2 v = analytic(wide_domain_point(q, width, height));
        return glm::dvec2(v.x * 0.5 * width, v.y * height);
    };
}

// A field in texels (a function of texel coordinates) sampled at the texel centres.
template <typename InTexels>
DoubleField sample_texel_centres(int width, int height, InTexels in_texels) {
    DoubleField field(width, height);
    field.fill([&](int x, int y) { return in_texels(glm::dvec2(x + 0.5, y + 0.5)); });
    return field;
}

// The continuous field whose samples make_flow rounds: `in_texels` everywhere, times the factor that makes its
// largest speed over the texel centres max_texels_per_step. At a texel centre it is, bit for bit, what
// sample_texel_centres(...).scaled_to(max_texels_per_step) rounds to float.
template <typename InTexels>
VelocityAt scaled_everywhere(int width, int height, double max_texels_per_step, InTexels in_texels) {
    const double scale =
        scale_for(sample_texel_centres(width, height, in_texels).largest_speed(), max_texels_per_step);
    return [in_texels, scale](glm::dvec2 q) { return in_texels(q) * scale; };
}

// Analytic fields on [-1,1]^2 sampled at the texel centres.
template <typename Analytic>
DoubleField sample_square(int width, int height, Analytic analytic) {
    return sample_texel_centres(width, height, square_in_texels(width, height, analytic));
}

// Analytic fields on [0,2]x[0,1] sampled at the texel centres.
template <typename Analytic>
DoubleField sample_wide(int width, int height, Analytic analytic) {
    return sample_texel_centres(width, height, wide_in_texels(width, height, analytic));
}

// The double gyre at `time`, unscaled (domain velocities carried into texels), for make_flow and for
// make_double_gyre_sequence, which scales all its frames by one factor.
DoubleField sample_double_gyre(int width, int height, double time);

// Smoothstep of t already mapped to [0, 1]: 0 and 1 with zero slope at both ends.
inline double smoothstep01(double t) {
    t = std::clamp(t, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

}  // namespace gsv::flow_detail
