#pragma once
// Frame timing that is honest on a software rasterizer: each frame is bracketed by glFinish and timed
// with a steady clock (GL timer queries do not see llvmpipe's rasterization), after a warm-up,
// and summarised by the median.
#include <functional>
#include <vector>

namespace gsv {

struct TimingStats {
    double median_ms = 0, min_ms = 0, max_ms = 0, mean_ms = 0;
    int frames = 0;
};

TimingStats summarize(std::vector<double> samples_ms);

class FrameMarks;

// Runs `frame` warmup + frames times; returns statistics of the timed frames. With `marks`, one mark before the
// first timed frame and one after each (common/timing/frame_marks.h).
TimingStats time_frames(const std::function<void()>& frame, int warmup, int frames, const FrameMarks* marks = nullptr);

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
