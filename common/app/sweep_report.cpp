#include "common/app/sweep_report.h"

#include "common/core/error.h"
#include "common/core/number_text.h"

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

// Every extra column any row has, in the order first seen: a series may measure what another cannot (lab 06's
// isosurface rows carry hit errors the DVR rows lack), and each name keeps one column.
std::vector<std::string> extra_columns(const std::vector<SweepRow>& rows) {
    std::vector<std::string> names;
    for (const auto& r : rows)
        for (const auto& [name, value] : r.extra)
            if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    return names;
}

const double* extra_value(const SweepRow& row, const std::string& name) {
    for (const auto& [n, value] : row.extra)
        if (n == name) return &value;
    return nullptr;
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
    const std::vector<std::string> extras = extra_columns(rows);
    for (const auto& name : extras) out << " " << std::string(14 - std::min<std::size_t>(14, name.size()), ' ') << name;
    // Values are right-aligned under their names, however long the names are.
    out << "\n";
    for (const auto& r : rows) {
        std::snprintf(line, sizeof line, "%-12s %-10s %10.3f %8.2f %10.3f %8d", r.series.c_str(), r.knob.c_str(),
                      r.median_ms, base_ms > 0 ? r.median_ms / base_ms : 0.0, r.rmse, r.max_diff);
        out << line;
        for (const auto& name : extras) {
            const int width = static_cast<int>(std::max<std::size_t>(14, name.size()));
            // %g: an error of 3e-8 must not print as 0.0000.
            if (const double* value = extra_value(r, name)) std::snprintf(line, sizeof line, " %*.4g", width, *value);
            else std::snprintf(line, sizeof line, " %*s", width, "-");
            out << line;
        }
        out << "\n";
    }
    return out.str();
}

std::string SweepReport::csv() const {
    std::ostringstream out;
    out << (series.empty() ? "series" : series) << "," << knob << ",median_ms,min_ms,rmse,max_diff";
    const std::vector<std::string> extras = extra_columns(rows);
    for (const auto& name : extras) out << "," << name;
    out << "\n";
    for (const auto& r : rows) {
        out << (r.series.empty() ? "-" : r.series) << "," << r.knob << "," << fixed(r.median_ms, 4) << ","
            << fixed(r.min_ms, 4) << "," << fixed(r.rmse, 4) << "," << r.max_diff;
        for (const auto& name : extras) {
            // An empty cell where this row has no such measure: gnuplot skips it.
            if (const double* value = extra_value(r, name)) out << "," << format_number(*value);
            else out << ",";
        }
        out << "\n";
    }
    return out.str();
}

std::string SweepReport::markdown() const {
    std::ostringstream out;
    out << "| " << (series.empty() ? "" : series + " | ") << knob << " | ms/frame | RMSE | max diff";
    const std::vector<std::string> extras = extra_columns(rows);
    for (const auto& name : extras) out << " | " << name;
    out << " |\n|";
    const std::size_t columns = (series.empty() ? 4 : 5) + extras.size();
    for (std::size_t i = 0; i < columns; ++i) out << (i < (series.empty() ? 1u : 2u) ? " --- |" : " ---: |");
    out << "\n";
    auto number = [](double value) { return format_number(value, 4); };
    for (const auto& r : rows) {
        out << "| " << (series.empty() ? "" : r.series + " | ") << r.knob << " | " << number(r.median_ms) << " | "
            << number(r.rmse) << " | " << r.max_diff;
        for (const auto& name : extras) {
            const double* value = extra_value(r, name);
            out << " | " << (value ? number(*value) : "-");
        }
        out << " |\n";
    }
    // A pipe table's caption: ": text" after a blank line.
    out << "\n: " << lab << ", " << width << "x" << height << ", " << gl << "; error against";
    for (const auto& r : reference) out << " " << r;
    out << ".\n";
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
    const auto md_path = dir / (lab + "-sweep.md");
    write_file(md_path, markdown());

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
    const std::vector<std::string> extras = extra_columns(rows);
    for (std::size_t i = 0; i < extras.size(); ++i)
        if (!plotted_error.empty() && extras[i] == plotted_error) {
            error_column = 7 + static_cast<int>(i);  // after series, knob, median_ms, min_ms, rmse, max_diff
            error_label = plotted_error;
        }
    plot(error_column, error_label);
    gp << "unset logscale y\n";
    plot(3, "median ms per frame");
    gp << "unset multiplot\n";
    write_file(gp_path, gp.str());

    std::vector<std::string> written{csv_path.string(), md_path.string(), gp_path.string()};
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
