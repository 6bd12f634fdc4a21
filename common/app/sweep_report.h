#pragma once
// The accuracy-versus-time table of a sweep: printed, written as CSV, and plotted with gnuplot.
#include "common/app/sweep_plan.h"
#include "common/timing/frame_work.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gsv {

struct SweepRow {
    std::string series;   // value of the lab's series parameter ("" when it has none)
    std::string knob;     // value of the accuracy knob
    double median_ms = 0, min_ms = 0;
    double p25_ms = 0, p75_ms = 0;  // the middle half of the frames: the spread beside the median
    double rmse = 0;      // image RMSE over RGB (0..255) against the reference
    int max_diff = 0;     // largest channel difference against the reference
    SweepMetrics extra;   // the lab's own error measures
    // What the frame asks of the device (Lab::frame_work's summary; empty: not stated), and against this device's
    // ceilings where they are known (common/timing/frame_work.h): the bound, the fraction of it reached, the limiter.
    std::string work;
    std::optional<Roofline> roofline;
};

struct SweepReport {
    std::string lab, knob, series, gl;
    std::vector<std::string> reference;
    std::string reference_name;  // what the error is measured against, in words (and whether shown converged)
    int width = 0, height = 0;
    std::vector<SweepRow> rows;
    std::string plotted_error;  // an extra column to plot as the error instead of the image RMSE; empty: RMSE

    std::string table() const;
    std::string csv() const;
    // The table as a Markdown pipe table, numbers to 4 significant digits, with a caption (pandoc's ": text")
    // naming the machine, the size and the reference: what the slides include.
    std::string markdown() const;
    // What accuracy costs, in one CSV line under a header: the cheapest setting (lowest median time) and the most
    // accurate one (lowest plotted error above 0: an error of 0 is the reference itself), each one's error and
    // time, the ratios between them, and each one's fraction of the bound this device's ceilings set with the
    // resource that sets it ("<=" before the fraction where the work is an upper bound; both empty where no ceilings
    // were measured or the lab states no work). `scripts/kit tradeoffs` gathers these across the labs.
    std::string summary() const;
    // Writes <lab>-sweep.csv, <lab>-sweep.md, <lab>-summary.csv, the gnuplot scripts and, when gnuplot is installed, <lab>-sweep.png
    // (error and time against the knob, the time beside the bound the ceilings set where measured) and <lab>-tradeoff.png (error against time, a point per setting labelled
    // with its knob value, a curve per series); returns the paths.
    std::vector<std::string> write(const std::filesystem::path& dir) const;

    // The error a row is plotted with (the RMSE or plotted_error's column; NaN where the row lacks it), and
    // whether every one there is is above zero, so the plots may take a log axis.
    double plotted_value(const SweepRow& row) const;
    bool all_positive_errors() const;
};

}  // namespace gsv
