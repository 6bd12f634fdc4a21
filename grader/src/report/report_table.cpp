#include "grader/src/report/report.h"
#include "grader/src/report/report_format.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <map>
#include <sstream>

namespace gsv {
namespace {

constexpr std::size_t kDetailBytes = 90;

// Width in characters, not bytes, so a name with an accent does not push its row out of line.
std::size_t display_width(const std::string& text) {
    return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    }));
}

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
    return text;
}

std::string pad_right(const std::string& text, std::size_t width) {
    const std::size_t w = display_width(text);
    return w >= width ? text : text + std::string(width - w, ' ');
}

std::string pad_left(const std::string& text, std::size_t width) {
    const std::size_t w = display_width(text);
    return w >= width ? text : std::string(width - w, ' ') + text;
}

struct Row {
    std::string lab, check, todo, status, points, detail;
    std::vector<std::string> below;  // a failing check's message in full, and the command that reproduces it
};

// Folds `text` into lines of at most `width` characters, at spaces where it can.
std::vector<std::string> folded(const std::string& text, std::size_t width) {
    std::vector<std::string> lines;
    std::string rest = text;
    while (display_width(rest) > width) {
        std::size_t cut = rest.rfind(' ', width);
        if (cut == std::string::npos || cut < width / 2) cut = width;
        lines.push_back(rest.substr(0, cut));
        rest = rest.substr(cut + (rest[cut] == ' ' ? 1 : 0));
    }
    if (!rest.empty()) lines.push_back(rest);
    return lines;
}

}  // namespace

std::string score_table(const GradeReport& report) {
    std::vector<Row> rows;
    rows.push_back({"lab", "check", "todo", "status", "points", "detail", {}});
    std::map<std::string, std::string> first_compile_error;  // lab -> the check that showed it
    for (const auto& r : report.results) {
        Row row{one_line(r.lab, 24), one_line(check_label(r), 40), one_line(r.todo, 16), status_name(r.status),
                format_points(r.points) + "/" + format_points(r.max_points), "", {}};
        const std::string detail = one_line(r.detail, 1000);
        if (r.status == CaseStatus::Passed || is_kit_fault(r.status)) {
            row.detail = one_line(r.detail, kDetailBytes);
        } else if (r.status == CaseStatus::ShaderCompileError && first_compile_error.count(r.lab + detail)) {
            row.detail = "the same error as " + first_compile_error[r.lab + detail];  // shown once a lab
        } else {
            if (r.status == CaseStatus::ShaderCompileError) first_compile_error[r.lab + detail] = check_label(r);
            for (const auto& line : folded(detail, kDetailBytes + 20)) row.below.push_back("    " + line);
            if (!r.reproduce.empty() && r.kind == "image") row.below.push_back("    reproduce: " + r.reproduce);
        }
        rows.push_back(std::move(row));
    }

    std::size_t w_lab = 0, w_check = 0, w_todo = 0, w_status = 0, w_points = 0;
    for (const auto& row : rows) {
        w_lab = std::max(w_lab, display_width(row.lab));
        w_check = std::max(w_check, display_width(row.check));
        w_todo = std::max(w_todo, display_width(row.todo));
        w_status = std::max(w_status, display_width(row.status));
        w_points = std::max(w_points, display_width(row.points));
    }

    std::ostringstream out;
    // The report opens with what the failures come down to (grader/src/diagnose/): the known mistakes that explain them.
    if (!report.diagnoses.empty()) {
        out << "what went wrong (the kit's known mistakes compared with your pictures)\n";
        for (const auto& d : report.diagnoses) {
            bool first_line = true;
            for (const auto& line : diagnosis_lines(d)) {
                const std::string head = first_line ? pad_right(one_line(d.lab, 24), 7) : std::string(7, ' ');
                first_line = false;
                const auto parts = folded(one_line(line, 1000), kDetailBytes + 30);
                for (std::size_t i = 0; i < parts.size(); ++i) out << "  " << (i == 0 ? head : std::string(7, ' ')) << (i == 0 ? "" : "    ") << parts[i] << "\n";
            }
        }
        out << "\n";
    }
    for (const auto& row : rows) {
        std::string line = pad_right(row.lab, w_lab) + "  " + pad_right(row.check, w_check) + "  " +
                           pad_right(row.todo, w_todo) + "  " + pad_right(row.status, w_status) + "  " +
                           pad_left(row.points, w_points) + "  " + row.detail;
        while (!line.empty() && line.back() == ' ') line.pop_back();
        out << line << "\n";
        for (const auto& below : row.below) out << below << "\n";
    }

    // Subtotals and the total share one layout, the slash of "x / y" in one column.
    const std::vector<std::string> labs = lab_order(report);
    std::size_t w_name = 0;
    for (const auto& lab : labs) w_name = std::max(w_name, display_width(lab));
    const auto score_cell = [](double score, double max) {
        return pad_left(format_points(score), 6) + " / " + pad_right(format_points(max), 6);
    };
    out << "\nper lab\n";
    for (const auto& lab : labs) {
        double score = 0, max = 0;
        int checks = 0, passed = 0;
        for (const auto& r : report.results) {
            if (r.lab != lab) continue;
            score += r.points;
            max += r.max_points;
            ++checks;
            if (r.status == CaseStatus::Passed) ++passed;
        }
        out << "  " << pad_right(lab, w_name) << "  " << score_cell(score, max) << "  " << passed << " of " << checks
            << " checks passed";
        if (const LabBuild* build = find_build(report, lab); build && build->ok) out << "; " << build->origin;
        out << "\n";
    }

    bool any_failed_build = false;
    for (const auto& b : report.builds) {
        if (b.ok) continue;
        if (!any_failed_build) out << "\nbuilds that failed\n";
        any_failed_build = true;
        const std::string first = first_error_line(b.log);
        out << "  " << b.lab << ": " << (first.empty() ? "(no compiler output)" : first) << "\n";
    }

    const double score = report.score(), max = report.max_score();
    out << "\n" << pad_right("total", std::max<std::size_t>(9, w_name + 4)) << pad_left(format_points(score), 6)
        << " / " << format_points(max);
    if (max > 0) out << "  (" << fixed(100.0 * score / max, 0) << "%)";
    out << "\n";
    std::string mode = report.mode.empty() ? "(not given)" : report.mode;
    if (report.hidden_included) mode += ", hidden cases";
    if (report.timing_included) mode += ", timing";
    out << "mode     " << one_line(mode, 200) << "\n";
    if (report.profile != "core") out << "profile  " << one_line(report.profile, 40) << " (the labs and the references ran on it)\n";
    if (!report.renderer.empty()) out << "renderer " << one_line(report.renderer, 200) << " (the labs ran on it)\n";
    if (!report.golden_renderers.empty()) out << "goldens  " << one_line(golden_renderers_text(report), 300) << "\n";
    if (report.hidden_included) {
        char seed[32];
        std::snprintf(seed, sizeof seed, "%" PRIu64, report.seed);
        out << "seed     " << seed << " (the hidden cases were drawn from it)\n";
    }
    out << "sandbox  " << (report.sandbox.empty() ? "(not given)" : one_line(report.sandbox, 200)) << "\n";
    if (!report.references.empty()) out << "references  " << one_line(report.references, 300) << "\n";
    if (!report.diagnosis_note.empty()) out << "diagnosis " << one_line(report.diagnosis_note, 300) << "\n";
    if (!report.regraded.empty() || !report.kept.empty())
        out << "regraded " << (report.regraded.empty() ? std::string("none") : joined(report.regraded))
            << (report.kept.empty() ? std::string() : "; kept from the last run (nothing they depend on changed): " + joined(report.kept))
            << "\n";
    return out.str();
}

}  // namespace gsv
