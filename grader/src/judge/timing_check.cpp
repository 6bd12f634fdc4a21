#include "grader/src/judge/timing_check.h"

#include "common/image/image_compare.h"
#include "grader/src/cases/draw.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>

namespace gsv {

CaseResult check_timing(const LabCases& lab, const GradeCase& c, const CaseResult& image, const LabRunner& student,
                        const ProcessLimits& student_limits, const LabRunner& reference, const ProcessLimits& reference_limits) {
    CaseResult t = image;
    t.kind = "timing";
    t.max_points = c.timing.points;
    t.points = 0;
    t.actual_png = t.expected_png = t.diff_png = "";
    t.output.clear();
    t.seconds = 0;
    std::vector<double> s, ref;
    std::optional<LabRun> failure;
    // The settings of every timed frame are drawn afresh, from entropy no one else sees: a frame cannot be drawn
    // (or copied from an earlier one) before the grader asks for it.
    std::random_device entropy;
    SeededDraw fresh((std::uint64_t(entropy()) << 32) ^ entropy(), lab.lab + "/" + c.name + "/timing");
    // Interleaved, so a machine that slows down slows both alike; the reference draws the same frames.
    auto measure = [&](int rounds) {
        for (int i = 0; i < rounds && !failure; ++i) {
            std::vector<std::vector<std::string>> challenges;
            for (int f = 0; f < lab.timing_frames; ++f) challenges.push_back(draw_settings(*c.timing.vary, fresh, c.settings));
            const LabRun a = student.render(lab.lab, lab, c, student_limits, &challenges);
            t.seconds += a.process.seconds;
            if (a.status != CaseStatus::Passed) {
                failure = a;
                return;
            }
            const LabRun b = reference.render(lab.lab + "_solution", lab, c, reference_limits, &challenges);
            if (b.status != CaseStatus::Passed) continue;
            // What was timed must be what was asked for: each timed frame against the reference's frame drawn with the
            // same settings, so a frame that skips its work, or an answer made before its challenge, is refused.
            for (std::size_t k = 0; k < a.frames.size() && k < b.frames.size(); ++k) {
                const ImageDiff diff = compare_images(a.frames[k], b.frames[k], lab.tolerance(c, true));
                if (diff.within(lab.tolerance(c, true))) continue;
                std::string asked;
                for (const auto& setting : challenges[k]) asked += (asked.empty() ? "" : " ") + setting;
                failure = a;
                failure->status = CaseStatus::Refused;
                failure->detail = "timed frame " + std::to_string(k + 1) + " of " + std::to_string(a.frames.size()) + " (" + asked +
                                  ") is not the frame the reference draws with those settings: " + diff.summary() +
                                  " (each timed frame must be the frame the grader asked for)";
                return;
            }
            s.push_back(a.median_ms);
            ref.push_back(b.median_ms);
        }
    };
    const double band = c.timing.max_ratio;
    auto ratio = [&] { return median(s) / std::max(1e-6, median(ref)); };
    measure(lab.timing_rounds);
    // Over the band, or near it (within 25% either way), one more measurement decides: with two rounds a single slow
    // process (a burst of other load) makes the median of the rounds' medians their mean, and failed an honest lab 01
    // at 2.31x once; the median of four rounds is not moved by one. Work that is truly slower is slower in every round.
    if (!failure && (ratio() > band || std::fabs(std::log(ratio() / band)) < std::log(1.25))) {
        measure(lab.timing_rounds);
        t.timing.remeasured = true;
    }
    t.timing.done = true;
    t.timing.student_ms = median(s);
    t.timing.reference_ms = median(ref);
    t.timing.ratio = ratio();
    t.timing.max_ratio = band;
    t.timing.rounds = static_cast<int>(s.size());
    if (failure) {
        t.status = failure->status;
        t.detail = "while timing: " + failure->detail;
        t.output = failure->process.output;
        return t;
    }
    char line[160];
    std::snprintf(line, sizeof line, "%.2f ms vs the reference's %.2f ms: %.2fx (band %.2gx)%s", t.timing.student_ms,
                  t.timing.reference_ms, t.timing.ratio, band, t.timing.remeasured ? ", measured twice" : "");
    t.detail = line;
    if (t.timing.ratio <= band) {
        t.status = CaseStatus::Passed;
        t.points = c.timing.points;
    } else {
        t.status = CaseStatus::TooSlow;
    }
    return t;
}

}  // namespace gsv
