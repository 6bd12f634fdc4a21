#include "common/timing/timing.h"

#include "common/gl/gl.h"
#include "common/core/error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <string>

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

TimingStats time_frames(const std::function<void()>& frame, int warmup, int frames) {
    glFinish();  // nothing queued before us may be charged to the first frame
    for (int i = 0; i < warmup; ++i) {
        frame();
        glFinish();
    }
    std::vector<double> samples;
    samples.reserve(static_cast<std::size_t>(std::max(frames, 0)));
    for (int i = 0; i < frames; ++i) {
        const double t0 = now_seconds();
        frame();
        glFinish();
        samples.push_back(1000.0 * (now_seconds() - t0));
        }
    return summarize(std::move(samples));
}

InterleavedTimes time_interleaved(const std::vector<TimedWork>& work, int warmup, int frames, int rounds) {
    if (frames < 1 || rounds < 1 || warmup < 0)
        throw Error("time_interleaved: frames and rounds must be at least 1 and warmup at least 0, got " + std::to_string(frames) +
                    ", " + std::to_string(rounds) + " and " + std::to_string(warmup));
    auto make_current = [&](std::size_t i) {
        if (work[i].prepare) work[i].prepare();
        work[i].frame();  // one untimed frame after each switch: a rebuilt program's first draw compiles on some drivers
        glFinish();
    };
    // A sample is a batch of frames lasting at least kMinSampleMs: a frame of a tenth of a millisecond is mostly
    // glFinish and the scheduler, and the other core's work lands on it whole.
    constexpr double kMinSampleMs = 20.0;
    std::vector<int> batch(work.size(), 1);
    for (std::size_t i = 0; i < work.size(); ++i) {
        make_current(i);
        for (int w = 0; w < warmup; ++w) work[i].frame();
        glFinish();
        const double t0 = now_seconds();
        work[i].frame();
        glFinish();
        const double one_ms = 1000.0 * (now_seconds() - t0);
        batch[i] = one_ms >= kMinSampleMs ? 1 : std::min(1000, static_cast<int>(std::ceil(kMinSampleMs / std::max(one_ms, 1e-3))));
    }
    InterleavedTimes times;
    std::vector<std::vector<double>> samples(work.size());
    times.round_medians.assign(work.size(), {});
    for (int round = 0; round < rounds; ++round)
        for (std::size_t i = 0; i < work.size(); ++i) {
            make_current(i);
            std::vector<double> this_round;
            for (int f = 0; f < frames; ++f) {
                const double t0 = now_seconds();
                for (int k = 0; k < batch[i]; ++k) work[i].frame();
                glFinish();
                this_round.push_back(1000.0 * (now_seconds() - t0) / batch[i]);
            }
            samples[i].insert(samples[i].end(), this_round.begin(), this_round.end());
            times.round_medians[i].push_back(summarize(this_round).median_ms);
        }
    for (auto& s : samples) times.stats.push_back(summarize(std::move(s)));
    return times;
}

TimeRatio InterleavedTimes::ratio(std::size_t a, std::size_t b) const {
    TimeRatio r;
    r.median = stats.at(b).median_ms > 0 ? stats.at(a).median_ms / stats.at(b).median_ms : 0.0;
    bool first = true;
    for (std::size_t k = 0; k < round_medians.at(a).size(); ++k) {
        const double denominator = round_medians[b][k];
        const double q = denominator > 0 ? round_medians[a][k] / denominator : 0.0;
        r.low = first ? q : std::min(r.low, q);
        r.high = first ? q : std::max(r.high, q);
        first = false;
    }
    return r;
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
