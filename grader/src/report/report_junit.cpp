#include "grader/src/report/report.h"
#include "grader/src/report/report_format.h"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace gsv {
namespace {

std::string xml(std::string_view raw) { return escape_markup(raw, MarkupPlace::Attribute); }

// Element text keeps its newlines readable.
std::string xml_text(std::string_view raw) { return escape_markup(raw, MarkupPlace::Text); }

std::string seconds(double s) { return fixed(std::isfinite(s) && s > 0 ? s : 0.0, 3); }

struct Counts {
    int tests = 0, failures = 0, errors = 0;
    double seconds = 0;
    void add(const CaseResult& r) {
        ++tests;
        if (is_kit_fault(r.status)) ++errors;
        else if (r.status != CaseStatus::Passed) ++failures;
        if (std::isfinite(r.seconds)) seconds += r.seconds;
    }
};

std::string counts_attributes(const Counts& c, double time) {
    return "tests=\"" + std::to_string(c.tests) + "\" failures=\"" + std::to_string(c.failures) + "\" errors=\"" +
           std::to_string(c.errors) + "\" skipped=\"0\" time=\"" + seconds(time) + "\"";
}

void property(std::ostringstream& out, const std::string& name, const std::string& value) {
    out << "      <property name=\"" << xml(name) << "\" value=\"" << xml(value) << "\"/>\n";
}

void testcase(std::ostringstream& out, const CaseResult& r) {
    std::string name = check_label(r);
    if (!r.todo.empty()) name += " (" + r.todo + ")";
    out << "    <testcase name=\"" << xml(name) << "\" classname=\"" << xml(r.lab) << "\" time=\"" << seconds(r.seconds)
        << "\"";
    if (r.status == CaseStatus::Passed) {
        out << "/>\n";
        return;
    }
    const char* element = is_kit_fault(r.status) ? "error" : "failure";
    out << ">\n      <" << element << " message=\"" << xml(one_line(status_line(r), 300)) << "\" type=\""
        << xml(status_name(r.status)) << "\">" << xml_text(check_output(r)) << "</" << element << ">\n";
    out << "    </testcase>\n";
}

}  // namespace

std::string junit_xml(const GradeReport& report) {
    Counts all;
    for (const auto& r : report.results) all.add(r);

    std::ostringstream out;
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out << "<testsuites name=\"gsv-grade\" " << counts_attributes(all, report.seconds) << ">\n";
    for (const auto& lab : lab_order(report)) {
        Counts counts;
        for (const auto& r : report.results)
            if (r.lab == lab) counts.add(r);
        const LabBuild* build = find_build(report, lab);
        out << "  <testsuite name=\"" << xml(lab) << "\" " << counts_attributes(counts, counts.seconds) << ">\n";
        out << "    <properties>\n";
        property(out, "mode", report.mode);
        property(out, "profile", report.profile);
        if (report.hidden_included) {
            char seed[32];
            std::snprintf(seed, sizeof seed, "%" PRIu64, report.seed);
            property(out, "seed", seed);
        }
        property(out, "sandbox", report.sandbox);
        if (build) property(out, "build", build->ok ? "ok" : "failed");
        out << "    </properties>\n";
        for (const auto& r : report.results)
            if (r.lab == lab) testcase(out, r);
        // The compiler's output belongs to the lab, not to any one check.
        if (build && !build->ok) out << "    <system-out>" << xml_text(build->log) << "</system-out>\n";
        out << "  </testsuite>\n";
    }
    out << "</testsuites>\n";
    return out.str();
}

}  // namespace gsv
