#include "reference/flow/lic_reference.h"

#include "common/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <thread>
#include <utility>

namespace gsv {
namespace {

using glm::dvec2;

void check_options(const char* who, const VelocityAt& velocity, const StreamlineOptions& options) {
    if (!velocity) throw Error(std::string(who) + ": no velocity field given");
    if (options.substeps < 1)
        throw Error(std::string(who) + ": substeps must be >= 1, got " + std::to_string(options.substeps));
}

// Normalised, the unit field turns sharply near a zero of the field (a streamline passing at distance d curves with
// radius about d) and is undefined at it. A piece of a step over which the direction turns by more than this cosine
// (3.6 degrees) is halved, and halved again, until the turn is gentle or the piece is shorter than kShortestPiece:
// then the streamline has met a zero, or circles one, closer than that, and ends there. At 8 substeps only curves
// of radius below 2 texels are halved, so the fixed substeps stand elsewhere. Measured on a streamline circling 0.7
// texels from a vortex's centre: 5e-3 texels off after 100 steps with a 14 degree threshold, 1e-6 with this one.
// Without normalising, the field is smooth and its speed (at most 4 texels a step) bounds the turn: no halving.
constexpr double kGentleTurn = 0.998;
constexpr double kShortestPiece = 1e-4;  // texels; a circling streamline ends within a few of these of its zero

// Moves streamlines forward (direction +1) or backward (-1) along `velocity`.
class Stepper {
public:
    Stepper(const VelocityAt& velocity, double direction, const StreamlineOptions& options)
        : velocity_(velocity), direction_(direction), options_(options) {}

    // One unit step of the streamline at `at`: options.substeps RK4 substeps. `ended` is set, and `at` stays put
    // from then on, where a normalised streamline has run into a zero of the field.
    void unit_step(dvec2& at, bool& ended) const {
        const double h = 1.0 / options_.substeps;
        for (int i = 0; i < options_.substeps && !ended; ++i) piece(at, h, ended);
    }

private:
    dvec2 raw(dvec2 q) const { return direction_ * velocity_(q); }

    dvec2 slope(dvec2 q) const {
        const dvec2 v = raw(q);
        if (!options_.normalized) return v;
        const double squared = glm::dot(v, v);
        if (squared > 1e-280) return v / std::sqrt(squared);
        // Slower speeds still have a direction, but their squares near the denormals (and are 0 below 1e-162):
        // hypot, which does not square them, is slower.
        const double speed = std::hypot(v.x, v.y);
        return speed > 0.0 ? v / speed : dvec2(0.0);
    }

    // One RK4 step of length h (time, or arc length when normalised), in halves where the unit field turns sharply.
    void piece(dvec2& at, double h, bool& ended) const {
        const dvec2 k1 = slope(at);
        if (options_.normalized && k1 == dvec2(0.0)) {
            ended = true;
            return;
        }
        const dvec2 k2 = slope(at + 0.5 * h * k1);
        const dvec2 k3 = slope(at + 0.5 * h * k2);
        const dvec2 k4 = slope(at + h * k3);
        if (options_.normalized && std::min({glm::dot(k1, k2), glm::dot(k1, k3), glm::dot(k1, k4)}) < kGentleTurn) {
            if (h > kShortestPiece) {
                piece(at, 0.5 * h, ended);
                if (!ended) piece(at, 0.5 * h, ended);
                return;
            }
            // Into a zero (the source's centre, backwards) the streamline ends on it: where the velocity along the
            // first slope changes sign, by linear interpolation, exact for a linear field. A zero passed to one side
            // is not on that line: the streamline ends where it is.
            const double before = glm::dot(raw(at), k1);  // |v| > 0, as k1 is not zero
            const double after = glm::dot(raw(at + h * k1), k1);
            if (after <= 0.0) at += before / (before - after) * h * k1;
            ended = true;
            return;
        }
        at += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }

    const VelocityAt& velocity_;
    double direction_;
    const StreamlineOptions& options_;
};

void check_sizes(const char* who, const std::vector<float>& noise, int width, int height) {
    for (const auto& [name, value] : {std::pair<const char*, int>{"width", width}, {"height", height}})
        if (value < 1 || value > kMaxFlowSide)
            throw Error(std::string(who) + ": " + name + " must be 1.." + std::to_string(kMaxFlowSide) + ", got " +
                        std::to_string(value));
    if (noise.size() != static_cast<std::size_t>(width) * height)
        throw Error(std::string(who) + ": the noise holds " + std::to_string(noise.size()) + " values, not " +
                    std::to_string(width) + "x" + std::to_string(height));
}

void check_length(const char* who, int length) {
    if (length < 0) throw Error(std::string(who) + ": a length must be >= 0, got " + std::to_string(length));
}

// rows(first, stride) on every core, the rows dealt out in turn so that each thread gets its share of the slow ones
// (a vortex's core, the border where streamlines end early). What a thread throws is rethrown here.
template <typename Rows>
void over_rows(int height, Rows rows) {
    const int threads = std::max(1, std::min(height, static_cast<int>(std::thread::hardware_concurrency())));
    std::vector<std::exception_ptr> failures(static_cast<std::size_t>(threads));
    const auto guarded = [&](int t) {
        try {
            rows(t, threads);
        } catch (...) {
            failures[static_cast<std::size_t>(t)] = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    try {
        for (int t = 1; t < threads; ++t) pool.emplace_back(guarded, t);
    } catch (...) {
        for (std::thread& worker : pool) worker.join();
        throw;
    }
    guarded(0);
    for (std::thread& worker : pool) worker.join();
    for (const std::exception_ptr& failure : failures)
        if (failure) std::rethrow_exception(failure);
}

// [0,W]x[0,H] with its edges, as the shader's streamlineContinues tests [0,1]^2; false for a NaN.
bool inside(dvec2 q, int width, int height) { return q.x >= 0.0 && q.x <= width && q.y >= 0.0 && q.y <= height; }

// GL_LINEAR with GL_CLAMP_TO_EDGE at texel coordinates q, in double: the four texels whose centres surround q,
// weighted by q's fractions past the lower ones; an index off the grid reads its edge texel.
double bilinear(const std::vector<float>& texels, int width, int height, dvec2 q) {
    const double u = q.x - 0.5, v = q.y - 0.5;
    const double fu = std::floor(u), fv = std::floor(v);
    const double a = u - fu, b = v - fv;
    // Clamped in double first: a point far off the grid must not overflow an int.
    const int iu = static_cast<int>(std::clamp(fu, -1.0, double(width)));
    const int iv = static_cast<int>(std::clamp(fv, -1.0, double(height)));
    const int i0 = std::clamp(iu, 0, width - 1), i1 = std::clamp(iu + 1, 0, width - 1);
    const int j0 = std::clamp(iv, 0, height - 1), j1 = std::clamp(iv + 1, 0, height - 1);
    const auto at = [&](int i, int j) { return double(texels[static_cast<std::size_t>(j) * width + i]); };
    const double bottom = at(i0, j0) + a * (at(i1, j0) - at(i0, j0));
    const double top = at(i0, j1) + a * (at(i1, j1) - at(i0, j1));
    return bottom + b * (top - bottom);
}

std::uint8_t to_level(double value) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
}

}  // namespace

dvec2 trace_streamline(const VelocityAt& velocity, dvec2 start, int steps, const StreamlineOptions& options) {
    check_options("trace_streamline", velocity, options);
    const Stepper stepper(velocity, steps < 0 ? -1.0 : 1.0, options);
    bool ended = false;
    for (int i = 0; i < std::abs(steps); ++i) stepper.unit_step(start, ended);
    return start;
}

std::vector<Image> exact_lic(const VelocityAt& velocity, const std::vector<float>& noise, int width, int height,
                             const std::vector<int>& lengths, const StreamlineOptions& options) {
    for (int length : lengths) check_length("exact_lic", length);
    ExactLic lic(velocity, noise, width, height, options);
    std::vector<int> ascending = lengths;
    std::sort(ascending.begin(), ascending.end());
    for (int length : ascending) lic.image(length);
    std::vector<Image> images;
    for (int length : lengths) images.push_back(lic.image(length));
    return images;
}

ExactLic::ExactLic(VelocityAt velocity, std::vector<float> noise, int width, int height, StreamlineOptions options)
    : velocity_(std::move(velocity)), noise_(std::move(noise)), width_(width), height_(height), options_(options) {
    check_options("exact_lic", velocity_, options_);
    check_sizes("exact_lic", noise_, width_, height_);
    halves_.reserve(2 * static_cast<std::size_t>(width_) * height_);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x)
            for (int d = 0; d < 2; ++d) halves_.push_back(Half{dvec2(x + 0.5, y + 0.5)});
}

const Image& ExactLic::image(int length) {
    check_length("exact_lic", length);
    check_options("exact_lic", velocity_, options_);
    if (const auto found = images_.find(length); found != images_.end()) return found->second;
    if (length < walked_) {
        ExactLic afresh(velocity_, noise_, width_, height_, options_);
        return images_[length] = afresh.image(length);
    }
    walk_to(length);
    return images_.at(length);
}

void ExactLic::walk_to(int length) {
    Image image(width_, height_);
    const Stepper steppers[2] = {{velocity_, 1.0, options_}, {velocity_, -1.0, options_}};
    over_rows(height_, [&](int first, int stride) {
        for (int y = first; y < height_; y += stride)
            for (int x = 0; x < width_; ++x) {
                Half* half = &halves_[2 * (static_cast<std::size_t>(y) * width_ + x)];
                for (int d = 0; d < 2; ++d)
                    for (int k = walked_; k < length && !half[d].left; ++k) {
                        steppers[d].unit_step(half[d].at, half[d].ended);
                        if (!inside(half[d].at, width_, height_)) {
                            half[d].left = true;
                            break;
                        }
                        half[d].sum += bilinear(noise_, width_, height_, half[d].at);
                        ++half[d].count;
                    }
                const double own = bilinear(noise_, width_, height_, dvec2(x + 0.5, y + 0.5));
                const double mean = (own + half[0].sum + half[1].sum) / (1 + half[0].count + half[1].count);
                std::uint8_t* pixel = image.at(x, height_ - 1 - y);
                pixel[0] = pixel[1] = pixel[2] = to_level(mean);
                pixel[3] = 255;
            }
    });
    walked_ = length;
    images_[length] = std::move(image);
}

}  // namespace gsv
