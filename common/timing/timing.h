#pragma once
// Frame timing that is honest on a software rasterizer: each frame is bracketed by glFinish and timed
// with a steady clock (GL timer queries do not see llvmpipe's rasterization), after a warm-up,
// and summarised by the median.
#include <cstddef>
#include <functional>
#include <vector>

namespace gsv {

struct TimingStats {
    double median_ms = 0, min_ms = 0, max_ms = 0, mean_ms = 0;
    double p25_ms = 0, p75_ms = 0;  // the middle half of the frames: the spread reported beside a median
    int frames = 0;
};

TimingStats summarize(std::vector<double> samples_ms);

// Runs `frame` warmup + frames times; returns statistics of the timed frames. (Under the grader a lab's own
// times count for nothing: the grader times frames itself, common/io/handin.h.)
TimingStats time_frames(const std::function<void()>& frame, int warmup, int frames);

// One of several things timed against each other: `prepare` (untimed, may be empty) makes it current (sets a
// parameter, binds a program), `frame` is one frame of it.
struct TimedWork {
    std::function<void()> prepare;
    std::function<void()> frame;
};

// A time ratio: of the overall medians, and the lowest and highest of the rounds' own ratios (its spread).
struct TimeRatio {
    double median = 0, low = 0, high = 0;
};

struct InterleavedTimes {
    std::vector<TimingStats> stats;                 // each thing over all its frames
    std::vector<std::vector<double>> round_medians;  // [thing][round]
    // Thing a's time over thing b's.
    TimeRatio ratio(std::size_t a, std::size_t b) const;
};

// Several things timed against each other fairly: a warm-up of each, then `rounds` rounds of A B C ..., `frames`
// glFinish-bracketed frames of each per round, so that a machine that slows down (another process, a clock change,
// a core taken away) slows them all alike. A frame shorter than a few milliseconds is timed in batches (the
// batch's time over its frames), so that glFinish and the scheduler do not decide it. Every time and ratio a sweep or a benchmark reports comes from here:
// lab 07's two shaders timed in separate blocks on this 2-core machine gave ratios of 2.91, 0.95 and 0.65 in three
// runs of the same sweep.
InterleavedTimes time_interleaved(const std::vector<TimedWork>& work, int warmup, int frames, int rounds);

// Frame-to-frame time in window mode, smoothed so the number on screen can be read.
class FrameClock {
public:
    void tick();                 // call once per frame
    double smoothed_ms() const { return smoothed_ms_; }
    double fps() const { return smoothed_ms_ > 0 ? 1000.0 / smoothed_ms_ : 0.0; }

private:
    double last_s_ = -1, smoothed_ms_ = 0;
};

double now_seconds();  // steady clock

}  // namespace gsv
