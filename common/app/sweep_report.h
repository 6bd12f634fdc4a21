#pragma once
// The accuracy-versus-time table of a sweep: printed, written as CSV, and plotted with gnuplot.
#include "common/app/app.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

struct SweepRow {
    std::string series;   // value of the lab's series parameter ("" when it has none)
    std::string knob;     // value of the accuracy knob
    double median_ms = 0, min_ms = 0;
    double rmse = 0;      // image RMSE over RGB (0..255) against the converged reference
    int max_diff = 0;     // largest channel difference against the reference
    SweepMetrics extra;   // the lab's own error measures
};

struct SweepReport {
    std::string lab, knob, series, gl;
    std::vector<std::string> reference;
    int width = 0, height = 0;
    std::vector<SweepRow> rows;
    std::string plotted_error;  // an extra column to plot as the error instead of the image RMSE; empty: RMSE

    std::string table() const;
    std::string csv() const;
    // The table as a Markdown pipe table, numbers to 4 significant digits, with a caption (pandoc's ": text")
    // naming the machine, the size and the reference: what the slides include.
    std::string markdown() const;
    // Writes <lab>-sweep.csv, <lab>-sweep.md, <lab>-sweep.gp and, when gnuplot is installed, <lab>-sweep.png;
    // returns the paths.
    std::vector<std::string> write(const std::filesystem::path& dir) const;
};

}  // namespace gsv
