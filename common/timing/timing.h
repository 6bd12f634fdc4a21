#pragma once
// Frame timing that is honest on a software rasterizer: each frame is bracketed by glFinish and timed
// with a steady clock (GL timer queries do not see llvmpipe's rasterization), after a warm-up,
// and summarised by the median.
#include <functional>
#include <vector>

namespace gsv {

struct TimingStats {
    double median_ms = 0, min_ms = 0, max_ms = 0, mean_ms = 0;
    double p25_ms = 0, p75_ms = 0;  // the middle half of the frames: the spread reported beside a median
    int frames = 0;
};

TimingStats summarize(std::vector<double> samples_ms);

class FrameMarks;

// Runs `frame` warmup + frames times; returns statistics of the timed frames. With `marks`, one mark before the
// first timed frame and one after each (common/timing/frame_marks.h).
TimingStats time_frames(const std::function<void()>& frame, int warmup, int frames, const FrameMarks* marks = nullptr);

// Several things timed against each other fairly: a warm-up of each, then `rounds` rounds of A B C ..., `frames`
// glFinish-bracketed frames of each per round, so that a machine that slows down (another process, a clock change)
// slows them all alike; each one's statistics over all its frames. `prepare[i]` (untimed) makes thing i current
// (sets a parameter, binds a program), `frame` draws one frame of whatever is current. Two things timed in separate
// blocks on this 2-core machine gave a ratio of 2.91, 0.95 and 0.65 in three runs; interleaved, they agree.
std::vector<TimingStats> time_interleaved(const std::vector<std::function<void()>>& prepare, const std::function<void()>& frame,
                                          int warmup, int frames, int rounds);

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
