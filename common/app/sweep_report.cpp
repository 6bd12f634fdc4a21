#include "common/app/sweep_report.h"

#include "common/core/error.h"
#include "common/core/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
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

bool ends_with(const std::string& text, const std::string& tail) {
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

// The columns a reader sees: NAME_lo and NAME_hi (common/app/sweep_metrics.h) go into NAME's cell.
std::vector<std::string> shown_columns(const std::vector<std::string>& all) {
    std::vector<std::string> shown;
    for (const auto& name : all) {
        const bool spread = (ends_with(name, "_lo") || ends_with(name, "_hi")) &&
                            std::find(all.begin(), all.end(), name.substr(0, name.size() - 3)) != all.end();
        if (!spread) shown.push_back(name);
    }
    return shown;
}

// A shown cell: the value to `digits` significant digits, with its spread where the row has one; "-" where the
// row lacks the measure.
std::string shown_cell(const SweepRow& row, const std::string& name, int digits) {
    const double* value = extra_value(row, name);
    if (!value) return "-";
    std::string cell = format_number(*value, digits);
    const double* lo = extra_value(row, name + "_lo");
    const double* hi = extra_value(row, name + "_hi");
    if (lo && hi) cell += " (" + format_number(*lo, 3) + "-" + format_number(*hi, 3) + ")";
    return cell;
}

bool any_work(const std::vector<SweepRow>& rows) {
    return std::any_of(rows.begin(), rows.end(), [](const SweepRow& r) { return !r.work.empty(); });
}

bool any_roofline(const std::vector<SweepRow>& rows) {
    return std::any_of(rows.begin(), rows.end(), [](const SweepRow& r) { return r.roofline.has_value(); });
}

// "<=" before a fraction whose work is the most the frame can do (the work column's "<= "): the frame reaches at
// most that share of the bound.
std::string at_most(const SweepRow& row) { return row.roofline && row.roofline->upper_bound ? "<=" : ""; }

// The share of the bound as a percentage for people: "41%", "<=41%"; "-" without a roofline.
std::string percent_cell(const SweepRow& row) {
    return row.roofline ? at_most(row) + fixed(100.0 * row.roofline->fraction(row.median_ms), 0) + "%" : "-";
}

// The limiters of a curve's rows, each once, in the order first seen: what its bound curve is titled with.
std::string limiters_of(const std::vector<SweepRow>& rows, const std::string& series) {
    std::string out;
    std::vector<std::string> seen;
    for (const auto& r : rows)
        if (r.series == series && r.roofline && std::find(seen.begin(), seen.end(), r.roofline->limiter) == seen.end()) {
            seen.push_back(r.roofline->limiter);
            out += (out.empty() ? "" : ", ") + r.roofline->limiter;
        }
    return out;
}

}  // namespace

std::string SweepReport::table() const {
    std::ostringstream out;
    out << lab << " sweep of " << knob << " at " << width << "x" << height << " on " << gl << "\n";
    out << "error against " << reference_name << "\n";
    out << "times: the median of the frames, timed interleaved with every other setting; spread: the middle half\n";
    const double base_ms = rows.empty() ? 1.0 : rows.front().median_ms;
    char line[512];
    std::snprintf(line, sizeof line, "%-12s %-10s %10s %17s %8s %10s %8s", series.empty() ? "" : series.c_str(),
                  knob.c_str(), "ms/frame", "spread", "x first", "RMSE", "max diff");
    out << line;
    const std::vector<std::string> extras = shown_columns(extra_columns(rows));
    const bool rooflines = any_roofline(rows);
    if (rooflines) out << " " << std::setw(9) << "ceiling";
    // Values are right-aligned under their names, however long the names are.
    std::vector<int> widths;
    for (const auto& name : extras) {
        std::size_t width = std::max<std::size_t>(14, name.size());
        for (const auto& r : rows) width = std::max(width, shown_cell(r, name, 4).size());
        widths.push_back(static_cast<int>(width));
        out << " " << std::string(static_cast<std::size_t>(widths.back()) - name.size(), ' ') << name;
    }
    out << "\n";
    for (const auto& r : rows) {
        const std::string spread = format_number(r.p25_ms, 4) + "-" + format_number(r.p75_ms, 4);
        std::snprintf(line, sizeof line, "%-12s %-10s %10.3f %17s %8.2f %10.3f %8d", r.series.c_str(), r.knob.c_str(),
                      r.median_ms, spread.c_str(), base_ms > 0 ? r.median_ms / base_ms : 0.0, r.rmse, r.max_diff);
        out << line;
        if (rooflines)
            out << " " << std::setw(9) << (r.roofline ? at_most(r) + fixed(100.0 * r.roofline->fraction(r.median_ms), 1) + "%" : "-");
        for (std::size_t k = 0; k < extras.size(); ++k) {
            // Significant digits: an error of 3e-8 must not print as 0.0000.
            std::snprintf(line, sizeof line, " %*s", widths[k], shown_cell(r, extras[k], 4).c_str());
            out << line;
        }
        out << "\n";
    }
    if (rooflines)
        for (const auto& r : rows)
            if (r.roofline) {
                out << "ceiling: the share of this device's bound the frame reaches; " << r.series << (r.series.empty() ? "" : " ")
                    << knob << "=" << r.knob << " is bound by " << r.roofline->limiter << " at "
                    << format_number(r.roofline->bound_ms, 3) << " ms (" << r.work << ")\n";
                break;
            }
    return out.str();
}

std::string SweepReport::csv() const {
    std::ostringstream out;
    out << (series.empty() ? "series" : series) << "," << knob << ",median_ms,min_ms,rmse,max_diff";
    const std::vector<std::string> extras = extra_columns(rows);
    for (const auto& name : extras) out << "," << name;
    const bool work = any_work(rows);
    if (work) out << ",work,bound_ms,fraction,limiter";
    out << ",p25_ms,p75_ms,reference\n";
    // The reference in words, in the last column (no commas in a CSV field that is not quoted).
    std::string words = reference_name;
    std::replace(words.begin(), words.end(), ',', ';');
    for (const auto& r : rows) {
        out << (r.series.empty() ? "-" : r.series) << "," << r.knob << "," << fixed(r.median_ms, 4) << ","
            << fixed(r.min_ms, 4) << "," << fixed(r.rmse, 4) << "," << r.max_diff;
        for (const auto& name : extras) {
            // An empty cell where this row has no such measure: gnuplot skips it.
            if (const double* value = extra_value(r, name)) out << "," << format_number(*value);
            else out << ",";
        }
        if (work) {
            out << "," << r.work;
            if (r.roofline)
                out << "," << format_number(r.roofline->bound_ms) << "," << format_number(r.roofline->fraction(r.median_ms), 4) << ","
                    << r.roofline->limiter;
            else
                out << ",,,";
        }
        out << "," << fixed(r.p25_ms, 4) << "," << fixed(r.p75_ms, 4) << "," << words << "\n";
    }
    return out.str();
}

std::string SweepReport::markdown() const {
    std::ostringstream out;
    out << "| " << (series.empty() ? "" : series + " | ") << knob << " | ms/frame (spread) | RMSE | max diff";
    // The share of this device's bound each frame reaches, where the ceilings are measured (as the table's).
    const bool rooflines = any_roofline(rows);
    if (rooflines) out << " | ceiling";
    const std::vector<std::string> extras = shown_columns(extra_columns(rows));
    for (const auto& name : extras) out << " | " << name;
    out << " |\n|";
    const std::size_t columns = (series.empty() ? 4 : 5) + (rooflines ? 1 : 0) + extras.size();
    for (std::size_t i = 0; i < columns; ++i) out << (i < (series.empty() ? 1u : 2u) ? " --- |" : " ---: |");
    out << "\n";
    auto number = [](double value) { return format_number(value, 4); };
    for (const auto& r : rows) {
        out << "| " << (series.empty() ? "" : r.series + " | ") << r.knob << " | " << number(r.median_ms) << " ("
            << number(r.p25_ms) << "-" << number(r.p75_ms) << ") | " << number(r.rmse) << " | " << r.max_diff;
        if (rooflines) out << " | " << percent_cell(r);
        for (const auto& name : extras) out << " | " << shown_cell(r, name, 4);
        out << " |\n";
    }
    // A pipe table's caption: ": text" after a blank line.
    out << "\n: " << lab << ", " << width << "x" << height << ", " << gl << "; error against " << reference_name
        << "; times interleaved" << (rooflines ? "; ceiling: the share of this device's bound the frame reaches (<=: at most)" : "")
        << ".\n";
    return out.str();
}

double SweepReport::plotted_value(const SweepRow& row) const {
    if (plotted_error.empty()) return row.rmse;
    const double* value = extra_value(row, plotted_error);
    return value ? *value : std::nan("");
}

bool SweepReport::all_positive_errors() const {
    for (const auto& r : rows) {
        const double e = plotted_value(r);
        if (e == e && !(e > 0)) return false;
    }
    return true;
}

std::string SweepReport::summary() const {
    const SweepRow* cheapest = nullptr;
    const SweepRow* accurate = nullptr;
    for (const auto& r : rows) {
        if (!cheapest || r.median_ms < cheapest->median_ms) cheapest = &r;
        const double e = plotted_value(r);
        if (e > 0 && (!accurate || e < plotted_value(*accurate))) accurate = &r;
    }
    auto setting = [&](const SweepRow* r) {
        return r ? (series.empty() ? "" : series + "=" + r->series + " ") + knob + "=" + r->knob : std::string("-");
    };
    auto number = [](double v) { return v == v ? format_number(v, 4) : std::string("-"); };
    std::string measure = plotted_error.empty() ? "rmse" : plotted_error;
    // Each one's share of the bound this device's ceilings set, and what sets it: empty where no ceilings were
    // measured or the lab states no work.
    auto roofline_cells = [&](const SweepRow* r) {
        if (!r || !r->roofline) return std::string(",");
        return at_most(*r) + format_number(r->roofline->fraction(r->median_ms), 4) + "," + r->roofline->limiter;
    };
    std::ostringstream out;
    out << "lab,knob,error,cheapest,cheapest_error,cheapest_ms,most_accurate,accurate_error,accurate_ms,time_ratio,error_ratio,"
           "cheapest_fraction,cheapest_limiter,accurate_fraction,accurate_limiter\n"
        << lab << "," << knob << "," << measure << "," << setting(cheapest) << ","
        << (cheapest ? number(plotted_value(*cheapest)) : "-") << "," << (cheapest ? number(cheapest->median_ms) : "-") << ","
        << setting(accurate) << "," << (accurate ? number(plotted_value(*accurate)) : "-") << ","
        << (accurate ? number(accurate->median_ms) : "-") << ",";
    if (cheapest && accurate && cheapest->median_ms > 0)
        out << number(accurate->median_ms / cheapest->median_ms) << "," << number(plotted_value(*cheapest) / plotted_value(*accurate));
    else
        out << "-,-";
    out << "," << roofline_cells(cheapest) << "," << roofline_cells(accurate) << "\n";
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
    const auto summary_path = dir / (lab + "-summary.csv");
    write_file(summary_path, summary());

    // One curve per series; x is the knob (log scale for numeric knobs spanning a decade or more). Sized for a slide:
    // shown at the slide's width, the text stays about 12 px high.
    std::vector<std::string> series_values;
    for (const auto& r : rows)
        if (series_values.empty() || series_values.back() != r.series) series_values.push_back(r.series);
    const bool numeric = all_numeric(rows);
    int error_column = 5;
    std::string error_label = "RMSE against the reference (0-255)";
    const std::vector<std::string> extras = extra_columns(rows);
    for (std::size_t i = 0; i < extras.size(); ++i)
        if (!plotted_error.empty() && extras[i] == plotted_error) {
            error_column = 7 + static_cast<int>(i);  // after series, knob, median_ms, min_ms, rmse, max_diff
            error_label = plotted_error + ", against the reference";
        }
    // The CSV's bound_ms: after the extra columns and the work (csv()).
    const int bound_column = 7 + static_cast<int>(extras.size()) + 1;
    const std::string data = csv_path.filename().string();
    const auto curve_title = [&](const std::string& sv) { return series.empty() ? knob : series + "=" + sv; };
    const auto only = [&](const std::string& sv, const std::string& column) {
        return "(strcol(1) eq '" + (sv.empty() ? std::string("-") : sv) + "' ? " + column + " : 1/0)";
    };
    std::ostringstream gp;
    gp << "# gnuplot script written by the kit's sweep mode; run: gnuplot " << gp_path.filename().string() << "\n"
       << "set datafile separator ','\nset terminal pngcairo size 1600,640 font 'DejaVu Sans,20'\n"
       << "set output '" << png_path.filename().string() << "'\n"
       << "set termoption noenhanced\n"  // before any text: knob names have underscores
       << "set multiplot layout 1,2 title '" << lab << ": error and time against " << knob << " (" << width << "x" << height << ")'\n"
       << "set key top right\nset grid\n";
    if (numeric) gp << "set logscale x 2\n";
    else gp << "set xtics rotate by -30\n";
    const std::string x = numeric ? "2" : "0";
    auto plot = [&](int column, const std::string& ylabel, bool bounds) {
        gp << "set xlabel '" << knob << "'\nset ylabel '" << ylabel << "'\nplot ";
        for (std::size_t i = 0; i < series_values.size(); ++i)
            gp << (i ? ", " : "") << "'" << data << "' using " << x << ":"
               << only(series_values[i], "$" + std::to_string(column)) << (numeric ? "" : ":xtic(2)")
               << " with linespoints lw 3 pt 7 ps 1.5 lt " << i + 1 << " title '" << curve_title(series_values[i]) << "'";
        // Beside each curve's times, dashed in its colour, the least time this device's ceilings allow its work
        // (the CSV's bound_ms): the gap between the two is the fraction reached. The key names them once per
        // limiter, with a black dash (a curve of no points), where a title per curve would not fit the panel.
        std::vector<std::string> keyed;
        for (std::size_t i = 0; bounds && i < series_values.size(); ++i) {
            const std::string limiters = limiters_of(rows, series_values[i]);
            if (limiters.empty()) continue;
            gp << ", '" << data << "' using " << x << ":" << only(series_values[i], "$" + std::to_string(bound_column))
               << " with linespoints lw 3 dt 2 pt 6 ps 1.5 lt " << i + 1 << " notitle";
            if (std::find(keyed.begin(), keyed.end(), limiters) == keyed.end()) keyed.push_back(limiters);
        }
        for (const auto& limiters : keyed)
            gp << ", NaN with lines lw 3 dt 2 lc 'black' title \"the fastest this device allows\\n(" << limiters << ")\"";
        gp << "\n";
    };
    // Errors fall by orders of magnitude as the knob converges; a zero cannot go on a log axis.
    const bool log_error = all_positive_errors();
    if (log_error) gp << "set logscale y\n";
    plot(error_column, error_label, false);
    if (log_error) gp << "unset logscale y\n";
    // Room above the curves for the key's bound lines, where there are bounds (the times rise towards it), and
    // between its lines, the bound's title taking two.
    if (any_roofline(rows)) gp << "set offsets 0, 0, graph 0.3, 0\nset key spacing 1.5\n";
    plot(3, "median ms per frame", true);
    gp << "unset multiplot\n";
    write_file(gp_path, gp.str());

    // What accuracy costs: error against time, log-log, points named by their knob values. A label is left out
    // where it would sit on the previous one of its curve (the first and the last always have one), and the
    // curves put theirs on alternate sides.
    const auto trade_gp = dir / (lab + "-tradeoff.gp");
    const auto trade_png = dir / (lab + "-tradeoff.png");
    std::ostringstream tp;
    tp << "# gnuplot script written by the kit's sweep mode; run: gnuplot " << trade_gp.filename().string() << "\n"
       << "set datafile separator ','\nset terminal pngcairo size 1200,800 font 'DejaVu Sans,22'\n"
       << "set output '" << trade_png.filename().string() << "'\nset termoption noenhanced\nset grid\n"
       << "set title '" << lab << ": what accuracy costs (" << knob << " beside each point)'\n"
       << "set xlabel 'median ms per frame'\nset ylabel '" << error_label << "'\n"
       << "set logscale x\n" << (log_error ? "set logscale y\n" : "") << "set key top right\n"
       << "set offsets graph 0.08, graph 0.08, graph 0.1, graph 0.1\n";
    double t_lo = 0, t_hi = 0, e_lo = 0, e_hi = 0;
    bool first = true;
    for (const auto& r : rows) {
        const double e = plotted_value(r);
        if (!(r.median_ms > 0) || !(e == e)) continue;
        const double t = std::log(r.median_ms), le = log_error ? std::log(e) : e;
        if (first) t_lo = t_hi = t, e_lo = e_hi = le, first = false;
        t_lo = std::min(t_lo, t), t_hi = std::max(t_hi, t), e_lo = std::min(e_lo, le), e_hi = std::max(e_hi, le);
    }
    for (std::size_t i = 0; i < series_values.size(); ++i) {
        std::vector<const SweepRow*> curve;
        for (const auto& r : rows)
            if (r.series == series_values[i] && r.median_ms > 0 && plotted_value(r) == plotted_value(r)) curve.push_back(&r);
        double last_x = -1, last_y = -1;
        for (std::size_t k = 0; k < curve.size(); ++k) {
            const double e = plotted_value(*curve[k]);
            const double x = (std::log(curve[k]->median_ms) - t_lo) / std::max(1e-9, t_hi - t_lo);
            const double y = ((log_error ? std::log(e) : e) - e_lo) / std::max(1e-9, e_hi - e_lo);
            const bool ends = k == 0 || k + 1 == curve.size();
            if (!ends && last_x >= 0 && std::hypot(x - last_x, y - last_y) < 0.07) continue;
            last_x = x, last_y = y;
            tp << "set label '" << curve[k]->knob << "' at " << curve[k]->median_ms << "," << e
               << (i % 2 ? " right offset -0.8,-0.9" : " left offset 0.8,0.9") << "\n";
        }
    }
    tp << "plot ";
    for (std::size_t i = 0; i < series_values.size(); ++i)
        tp << (i ? ", " : "") << "'" << data << "' using 3:" << only(series_values[i], "$" + std::to_string(error_column))
           << " with linespoints lw 3 pt 7 ps 1.8 title '" << curve_title(series_values[i]) << "'";
    tp << "\n";
    write_file(trade_gp, tp.str());

    std::vector<std::string> written{csv_path.string(), md_path.string(), summary_path.string(), gp_path.string(), trade_gp.string()};
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
        std::fprintf(stderr, "sweep: gnuplot not installed: wrote the CSV and the plot scripts only\n");
        return written;
    }
    for (const auto& [script, png] : {std::pair{gp_path, png_path}, std::pair{trade_gp, trade_png}}) {
        const std::string command = "cd \"" + dir.string() + "\" && gnuplot \"" + script.filename().string() + "\" 2>&1";
        if (std::system(command.c_str()) == 0) written.push_back(png.string());
        else std::fprintf(stderr, "sweep: gnuplot failed on %s; the CSV is complete\n", script.string().c_str());
    }
    return written;
}

}  // namespace gsv
