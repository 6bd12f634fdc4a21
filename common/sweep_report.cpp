#include "common/sweep_report.h"

#include "common/error.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace gsv {
namespace {

std::string fixed(double v, int digits) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
    return buffer;
}

bool all_numeric(const std::vector<SweepRow>& rows) {
    for (const auto& r : rows) {
        char* end = nullptr;
        std::strtod(r.knob.c_str(), &end);
        if (end == r.knob.c_str() || *end != '\0') return false;
    }
    return true;
}

void write_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path);
    if (!out || !(out << text)) throw Error("cannot write '" + path.string() + "'");
}

}  // namespace

std::string SweepReport::table() const {
    std::ostringstream out;
    out << lab << " sweep of " << knob << " at " << width << "x" << height << " on " << gl << "\n";
    out << "error is measured against the converged reference:";
    for (const auto& r : reference) out << " " << r;
    out << "\n";
    const double base_ms = rows.empty() ? 1.0 : rows.front().median_ms;
    char line[512];
    std::snprintf(line, sizeof line, "%-12s %-10s %10s %8s %10s %8s", series.empty() ? "" : series.c_str(),
                  knob.c_str(), "ms/frame", "x first", "RMSE", "max diff");
    out << line;
    if (!rows.empty())
        for (const auto& [name, value] : rows.front().extra) out << " " << std::string(14 - std::min<std::size_t>(14, name.size()), ' ') << name;
    // Values are right-aligned under their names, however long the names are.
    out << "\n";
    for (const auto& r : rows) {
        std::snprintf(line, sizeof line, "%-12s %-10s %10.3f %8.2f %10.3f %8d", r.series.c_str(), r.knob.c_str(),
                      r.median_ms, base_ms > 0 ? r.median_ms / base_ms : 0.0, r.rmse, r.max_diff);
        out << line;
        for (const auto& [name, value] : r.extra) {
            // %g: an error of 3e-8 must not print as 0.0000.
            std::snprintf(line, sizeof line, " %*.4g", static_cast<int>(std::max<std::size_t>(14, name.size())), value);
            out << line;
        }
        out << "\n";
    }
    return out.str();
}

std::string SweepReport::csv() const {
    std::ostringstream out;
    out << (series.empty() ? "series" : series) << "," << knob << ",median_ms,min_ms,rmse,max_diff";
    if (!rows.empty())
        for (const auto& [name, value] : rows.front().extra) out << "," << name;
    out << "\n";
    for (const auto& r : rows) {
        out << (r.series.empty() ? "-" : r.series) << "," << r.knob << "," << fixed(r.median_ms, 4) << ","
            << fixed(r.min_ms, 4) << "," << fixed(r.rmse, 4) << "," << r.max_diff;
        for (const auto& [name, value] : r.extra) {
            char number[32];
            std::snprintf(number, sizeof number, "%.6g", value);
            out << "," << number;
        }
        out << "\n";
    }
    return out.str();
}

std::vector<std::string> SweepReport::write(const std::filesystem::path& dir) const {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw Error("cannot create '" + dir.string() + "': " + ec.message());
    const auto csv_path = dir / (lab + "-sweep.csv");
    const auto gp_path = dir / (lab + "-sweep.gp");
    const auto png_path = dir / (lab + "-sweep.png");
    write_file(csv_path, csv());

    // One curve per series; x is the knob (log scale for numeric knobs spanning a decade or more).
    std::vector<std::string> series_values;
    for (const auto& r : rows)
        if (series_values.empty() || series_values.back() != r.series) series_values.push_back(r.series);
    const bool numeric = all_numeric(rows);
    std::ostringstream gp;
    gp << "# gnuplot script written by the kit's sweep mode; run: gnuplot " << gp_path.filename().string() << "\n"
       << "set datafile separator ','\nset terminal pngcairo size 1200,460 font ',10'\n"
       << "set output '" << png_path.filename().string() << "'\n"
       << "set multiplot layout 1,2 title '" << lab << ": what accuracy costs in time (" << width << "x" << height << ")'\n"
       << "set termoption noenhanced\nset key top right\nset grid\n";
    if (numeric) gp << "set logscale x 2\n";
    else gp << "set xtics rotate by -30\n";
    auto plot = [&](int column, const std::string& ylabel) {
        gp << "set xlabel '" << knob << "'\nset ylabel '" << ylabel << "'\nplot ";
        for (std::size_t i = 0; i < series_values.size(); ++i) {
            const std::string& sv = series_values[i].empty() ? std::string("-") : series_values[i];
            gp << (i ? ", " : "") << "'" << csv_path.filename().string() << "' using "
               << (numeric ? "2" : "0") << ":(strcol(1) eq '" << sv << "' ? $" << column << " : 1/0)"
               << (numeric ? "" : ":xtic(2)") << " with linespoints lw 2 title '"
               << (series.empty() ? knob : series + "=" + sv) << "'";
        }
        gp << "\n";
    };
    gp << "set logscale y\n";  // errors fall by orders of magnitude as the knob converges
    int error_column = 5;
    std::string error_label = "RMSE against the reference (0-255)";
    if (!plotted_error.empty() && !rows.empty())
        for (std::size_t i = 0; i < rows.front().extra.size(); ++i)
            if (rows.front().extra[i].first == plotted_error) {
                error_column = 7 + static_cast<int>(i);  // after series, knob, median_ms, min_ms, rmse, max_diff
                error_label = plotted_error;
            }
    plot(error_column, error_label);
    gp << "unset logscale y\n";
    plot(3, "median ms per frame");
    gp << "unset multiplot\n";
    write_file(gp_path, gp.str());

    std::vector<std::string> written{csv_path.string(), gp_path.string()};
    const std::string command = "cd \"" + dir.string() + "\" && gnuplot \"" + gp_path.filename().string() + "\" 2>&1";
    if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
        if (std::system(command.c_str()) == 0) written.push_back(png_path.string());
        else std::fprintf(stderr, "sweep: gnuplot failed on %s; the CSV is complete\n", gp_path.string().c_str());
    } else {
        std::fprintf(stderr, "sweep: gnuplot not installed: wrote the CSV and the plot script only\n");
    }
    return written;
}

}  // namespace gsv
