#pragma once
// Work an interactive frame spreads over frames (lab 05 catches its simulation up a few steps a frame), paced by the
// time frames take here, whatever the device and however large one step is. Without it lab 05 took a fixed 32 steps
// a frame: 32 steps of a million particles held the browser's page for seconds a frame on llvmpipe, where a small GPU
// takes them in a blink.
//
// The time of a frame is the gap to the next: a browser (and a window's swap) holds the next frame back until the GPU
// has done the last one. A gap after a frame that finished its work is idle time (nothing changed) and is not learnt.
// Each frame's work is scaled so the next gap meets the target: `target_s`, or twice a one-step frame's gap where that
// is longer (drawing alone can take longer than the target: then a frame steps about as long as it draws, so catching
// up takes about twice the steps' own time, not one drawing per step). The work at most doubles from one frame to
// the next, so one short gap (noise) cannot bring on a long frame.
// No GL here: the clock is passed in, so the pacing is testable without a context or a wait.
#include <optional>

namespace gsv {

class WorkPacer {
public:
    // `first_budget`: the work the first frame may take before anything is learnt, in the caller's units of work
    // (lab 05: particle steps); `target_s`: the time a frame should take where drawing leaves room.
    explicit WorkPacer(double first_budget, double target_s = 0.25) : budget_(first_budget), target_s_(target_s) {}

    // How many steps of `cost` units each this frame takes, at `now` seconds (a steady clock): at least 1, at most
    // `wanted` and `most`. Call once a frame that has steps to take, then done(more_left).
    long steps(long wanted, double cost, long most, double now);
    // After the frame: whether work is left for the next one (the next frame's gap is then the time this one took).
    void done(bool more_left) { measuring_ = more_left; }

    double budget() const { return budget_; }

private:
    double budget_;           // units of work a frame may take
    double target_s_;
    bool measuring_ = false;  // the last frame had work left: the gap to this one is its time
    double last_now_ = 0;
    double last_work_ = 0;    // the units the last frame took
    double last_cost_ = 0;    // the units of one step then (a new count forgets the one-step gap)
    std::optional<double> one_step_s_;  // the gap after a frame of one step: mostly drawing, where it is long
};

}  // namespace gsv
