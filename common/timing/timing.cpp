#include "common/timing/timing.h"

#include "common/gl/gl.h"
#include "common/timing/frame_marks.h"

#include <algorithm>
#include <chrono>
#include <numeric>

namespace gsv {

double now_seconds() {
    using clock = std::chrono::steady_clock;
    return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

TimingStats summarize(std::vector<double> samples_ms) {
    TimingStats stats;
    if (samples_ms.empty()) return stats;
    std::sort(samples_ms.begin(), samples_ms.end());
    const std::size_t n = samples_ms.size();
    stats.frames = static_cast<int>(n);
    stats.min_ms = samples_ms.front();
    stats.max_ms = samples_ms.back();
    stats.median_ms = n % 2 ? samples_ms[n / 2] : 0.5 * (samples_ms[n / 2 - 1] + samples_ms[n / 2]);
    // Quartiles by linear interpolation between order statistics.
    const auto quantile = [&](double q) {
        const double at = q * static_cast<double>(n - 1);
        const std::size_t lo = static_cast<std::size_t>(at);
        const std::size_t hi = std::min(lo + 1, n - 1);
        return samples_ms[lo] + (at - static_cast<double>(lo)) * (samples_ms[hi] - samples_ms[lo]);
    };
    stats.p25_ms = quantile(0.25);
    stats.p75_ms = quantile(0.75);
    stats.mean_ms = std::accumulate(samples_ms.begin(), samples_ms.end(), 0.0) / static_cast<double>(n);
    return stats;
}

TimingStats time_frames(const std::function<void()>& frame, int warmup, int frames, const FrameMarks* marks) {
    glFinish();  // nothing queued before us may be charged to the first frame
    for (int i = 0; i < warmup; ++i) {
        frame();
        glFinish();
    }
    std::vector<double> samples;
    samples.reserve(static_cast<std::size_t>(std::max(frames, 0)));
    if (marks) marks->mark();
    for (int i = 0; i < frames; ++i) {
        const double t0 = now_seconds();
        frame();
        glFinish();
        samples.push_back(1000.0 * (now_seconds() - t0));
        if (marks) marks->mark();
    }
    return summarize(std::move(samples));
}

std::vector<TimingStats> time_interleaved(const std::vector<std::function<void()>>& prepare, const std::function<void()>& frame,
                                          int warmup, int frames, int rounds) {
    std::vector<std::vector<double>> samples(prepare.size());
    for (std::size_t i = 0; i < prepare.size(); ++i) {
        prepare[i]();
        for (int w = 0; w < warmup; ++w) frame();
        glFinish();
    }
    for (int round = 0; round < rounds; ++round)
        for (std::size_t i = 0; i < prepare.size(); ++i) {
            prepare[i]();
            frame();  // one untimed frame after the switch: a rebuilt program's first draw compiles on some drivers
            glFinish();
            for (int f = 0; f < frames; ++f) {
                const double t0 = now_seconds();
                frame();
                glFinish();
                samples[i].push_back(1000.0 * (now_seconds() - t0));
            }
        }
    std::vector<TimingStats> stats;
    for (auto& s : samples) stats.push_back(summarize(std::move(s)));
    return stats;
}

void FrameClock::tick() {
    const double t = now_seconds();
    if (last_s_ >= 0) {
        const double ms = 1000.0 * (t - last_s_);
        smoothed_ms_ = smoothed_ms_ == 0 ? ms : 0.9 * smoothed_ms_ + 0.1 * ms;
    }
    last_s_ = t;
}

}  // namespace gsv
