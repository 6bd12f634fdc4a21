#include "grader/src/report/report_format.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>

namespace gsv {
namespace {

bool mentions_error(std::string_view line) {
    std::string lower(line);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    return lower.find("error") != std::string::npos;
}

bool blank(std::string_view line) {
    return std::all_of(line.begin(), line.end(), [](unsigned char c) { return std::isspace(c); });
}

}  // namespace

std::string check_label(const CaseResult& result) {
    return result.kind == "timing" ? result.name + " [time]" : result.name;
}

std::string check_title(const CaseResult& result) {
    std::string title = result.lab + "/" + check_label(result);
    if (!result.todo.empty()) title += " (" + result.todo + ")";
    return title;
}

std::string status_line(const CaseResult& result) {
    std::string line = status_name(result.status);
    if (!result.detail.empty()) line += ": " + result.detail;
    return line;
}

std::string check_output(const CaseResult& result) {
    std::string text = status_line(result);
    if (result.status != CaseStatus::Passed && result.kind == "image" && !result.reproduce.empty())
        text += "\nreproduce: " + result.reproduce;
    if (!result.output.empty()) text += "\n" + result.output;
    return text;
}


std::string golden_renderers_text(const GradeReport& report) {
    std::string text, first;
    bool one = true;
    for (const auto& [lab, renderer] : report.golden_renderers) {
        if (first.empty()) first = renderer;
        one = one && renderer == first;
        text += (text.empty() ? "" : "; ") + lab + ": " + renderer;
    }
    return one ? "rendered on " + first : text;
}

std::string fixed(double value, int digits) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
    return buffer;
}

std::string format_points(double points) {
    std::string text = fixed(points, 2);
    if (text.find('.') != std::string::npos) {
        while (text.back() == '0') text.pop_back();
        if (text.back() == '.') text.pop_back();
    }
    return text == "-0" ? "0" : text;
}

std::string first_error_line(std::string_view log) {
    std::string_view first_text;
    std::size_t start = 0;
    while (start < log.size()) {
        std::size_t end = log.find('\n', start);
        if (end == std::string_view::npos) end = log.size();
        const std::string_view line = log.substr(start, end - start);
        if (mentions_error(line)) return one_line(line, 200);
        if (first_text.empty() && !blank(line)) first_text = line;
        start = end + 1;
    }
    return one_line(first_text, 200);
}

std::string base64(std::string_view bytes) {
    static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    const auto at = [&](std::size_t k) { return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[k])); };
    for (; i + 3 <= bytes.size(); i += 3) {
        const std::uint32_t group = (at(i) << 16) | (at(i + 1) << 8) | at(i + 2);
        out += alphabet[(group >> 18) & 63];
        out += alphabet[(group >> 12) & 63];
        out += alphabet[(group >> 6) & 63];
        out += alphabet[group & 63];
    }
    const std::size_t rest = bytes.size() - i;
    if (rest > 0) {
        const std::uint32_t group = (at(i) << 16) | (rest == 2 ? at(i + 1) << 8 : 0);
        out += alphabet[(group >> 18) & 63];
        out += alphabet[(group >> 12) & 63];
        out += rest == 2 ? alphabet[(group >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

std::vector<std::string> lab_order(const GradeReport& report) {
    std::vector<std::string> labs;
    const auto add = [&](const std::string& lab) {
        if (std::find(labs.begin(), labs.end(), lab) == labs.end()) labs.push_back(lab);
    };
    for (const auto& r : report.results) add(r.lab);
    for (const auto& b : report.builds) add(b.lab);
    return labs;
}

const LabBuild* find_build(const GradeReport& report, const std::string& lab) {
    for (const auto& b : report.builds)
        if (b.lab == lab) return &b;
    return nullptr;
}

std::vector<std::string> diagnosis_lines(const LabDiagnosis& d) {
    std::vector<std::string> lines;
    const auto quoted_list = [](const std::vector<std::string>& names) {
        std::string text;
        for (std::size_t i = 0; i < names.size(); ++i)
            text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + ("'" + names[i] + "'");
        return text;
    };
    if (!d.found.empty()) {
        std::size_t explained = 0;
        for (const auto& f : d.found) explained += f.cases.size();
        const std::string of = std::to_string(explained) + " of your " + std::to_string(d.failing.size()) + " failing case" +
                               (d.failing.size() == 1 ? "" : "s");
        lines.push_back(d.found.size() == 1 ? "one known mistake explains " + of + ":"
                                            : std::to_string(d.found.size()) + " known mistakes explain " + of + ":");
        for (const auto& f : d.found) {
            std::string line = "  " + f.todo + ": " + f.says + " (sheet: " + f.sheet + ")";
            if (d.found.size() > 1) line += std::string(f.with_earlier ? "; with the mistakes above, " : "; ") + "cases " + quoted_list(f.cases);
            lines.push_back(line);
        }
    }
    if (!d.unexplained.empty()) {
        std::string line = "no known mistake matches " + quoted_list(d.unexplained);
        if (!d.compare.empty()) line += "; compare yours with the reference: " + d.compare;
        lines.push_back(line);
    }
    if (!d.not_started.empty()) {
        std::string todos;
        for (const auto& t : d.not_started) todos += (todos.empty() ? "" : ", ") + t;
        lines.push_back("not started: " + todos);
    }
    if (!d.way_in.empty()) lines.push_back("the way in: " + d.way_in);
    return lines;
}

LabDiagnosis student_diagnosis(const LabDiagnosis& d, const GradeReport& report) {
    const auto is_public = [&](const std::string& name) {
        return std::any_of(report.results.begin(), report.results.end(),
                           [&](const CaseResult& r) { return r.lab == d.lab && r.name == name && r.visibility == "public"; });
    };
    const auto public_only = [&](const std::vector<std::string>& names) {
        std::vector<std::string> kept;
        for (const auto& n : names)
            if (is_public(n)) kept.push_back(n);
        return kept;
    };
    LabDiagnosis out;
    out.lab = d.lab;
    out.failing = public_only(d.failing);
    for (const auto& f : d.found) {
        MistakeFound m = f;
        m.cases = public_only(f.cases);
        if (!m.cases.empty()) out.found.push_back(std::move(m));
    }
    out.unexplained = public_only(d.unexplained);
    out.not_started = d.not_started;
    out.compare = d.compare;
    out.way_in = d.way_in;
    return out;
}

}  // namespace gsv
