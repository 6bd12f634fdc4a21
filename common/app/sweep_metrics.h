#pragma once
// A sweep column with its spread: a time or a ratio goes in as three columns, NAME, NAME_lo and NAME_hi. The
// table and the Markdown show them as one cell, "median (lo-hi)"; the CSV keeps all three for plots.
#include "common/app/sweep_plan.h"
#include "common/timing/timing.h"

#include <string>

namespace gsv {

// How a lab times two shaders against each other inside one sweep point (time_interleaved): rounds of a few
// frames each, enough that three runs of the same sweep agree within 10% on every ratio on a 2-core machine.
inline constexpr int kCompareWarmup = 2;
inline constexpr int kCompareFrames = 4;
inline constexpr int kCompareRounds = 9;

// The median with the middle half of the frames (p25-p75).
inline void add_time(SweepMetrics& metrics, const std::string& name, const TimingStats& stats) {
    metrics.emplace_back(name, stats.median_ms);
    metrics.emplace_back(name + "_lo", stats.p25_ms);
    metrics.emplace_back(name + "_hi", stats.p75_ms);
}

// The ratio of the medians with the lowest and highest of the rounds' ratios.
inline void add_ratio(SweepMetrics& metrics, const std::string& name, const TimeRatio& ratio) {
    metrics.emplace_back(name, ratio.median);
    metrics.emplace_back(name + "_lo", ratio.low);
    metrics.emplace_back(name + "_hi", ratio.high);
}

}  // namespace gsv
