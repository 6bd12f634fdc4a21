#pragma once
// One process per lab (served, grader/src/run/lab_serve.h) against one process per case: two gradings of the same
// thing compared check for check, as results.json gives them to the student (status, score, status line). Used by
// tests/test_grader_serve.cpp and by the mutation tests (tests/test_grader_mutants.cpp), which grade every mutant and
// variant both ways.
#include "catch.hpp"

#include "common/io/json.h"
#include "grader/src/grade/grade.h"
#include "grader/src/report/report.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <string>

namespace gsv::test {

// Each check's status and score, then its status line (its detail).
inline std::map<std::string, std::string> graded_checks(const GradeReport& report) {
    std::map<std::string, std::string> checks;
    const Json results = parse_json(gradescope_json(report), "results.json");
    for (const Json& t : results.array_at("tests").as_array()) {
        const std::string output = t.string_at("output");
        checks[t.string_at("name")] = t.string_at("status") + " | " + std::to_string(t.number_at("score")) + " | " +
                                      output.substr(0, output.find('\n'));
    }
    return checks;
}

// A row as a racy lab keeps it from run to run: its status, its score and its detail without the numbers.
inline std::string racy_row(const std::string& row) {
    const std::size_t detail = row.rfind(" | ");
    std::string text = row.substr(detail + 3);
    text.erase(std::remove_if(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); }), text.end());
    return row.substr(0, detail) + " | " + text;
}

// Checks every check of the two gradings alike. `racy`: a lab whose invocations race (tests/mutants/'s "racy" and
// "racy_undone": lab 05's work-group mutants and L05-T2 left undone, two of whose invocations move one particle) draws a pixel or two otherwise from run to run,
// whatever runs it (seen with one process per case: 115,541 and 115,543 particles off): for it the detail's numbers
// are left out.
// Returns how many of the per-lab checks passed only when rendered again alone (kPassedOnlyAlone, grade.h): their
// status line is held alike without that note, which says so to the student. `details` false: status and score only,
// for a lab that keeps state between cases, whose passing pictures may differ within the tolerance after other cases.
inline int check_graded_alike(const GradeReport& per_case, const GradeReport& per_lab, const std::string& what, bool racy = false,
                              bool details = true) {
    auto a = graded_checks(per_case), b = graded_checks(per_lab);
    int passed_only_alone = 0;
    for (auto& entry : b)
        if (const auto at = entry.second.find(kPassedOnlyAlone); at != std::string::npos) {
            entry.second.erase(at, std::string(kPassedOnlyAlone).size());
            ++passed_only_alone;
        }
    if (!details)
        for (auto* checks : {&a, &b})
            for (auto& entry : *checks) entry.second = entry.second.substr(0, entry.second.rfind(" | "));
    if (racy)
        for (auto* checks : {&a, &b})
            for (auto& entry : *checks) entry.second = racy_row(entry.second);
    std::string differences;
    for (const auto& [name, row] : a)
        if (const auto it = b.find(name); it == b.end() || it->second != row)
            differences += name + ":\n  per case: " + row + "\n  per lab:  " + (it == b.end() ? "(missing)" : it->second) + "\n";
    for (const auto& [name, row] : b)
        if (!a.count(name)) differences += name + ": per lab only: " + row + "\n";
    INFO(what << " graded with one process per case and with one per lab:\n" << differences);
    CHECK(!a.empty());
    CHECK(differences.empty());
    return passed_only_alone;
}

}  // namespace gsv::test
