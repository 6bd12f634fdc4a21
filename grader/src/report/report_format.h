#pragma once
// Text helpers the reports share, so the table, results.json, JUnit and HTML name and describe a
// check the same way. Student output may hold any bytes, so everything that embeds it goes through
// these first.
#include "grader/src/core/grade_result.h"
#include "grader/src/core/safe_text.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace gsv {

// "phong", or "phong [time]" for the timing check of the same case.
std::string check_label(const CaseResult& result);
// "lab01/phong (L01-T3)"; the todo part is left out when the case names none.
std::string check_title(const CaseResult& result);
// "wrong image: max diff 37, ..." or just the status name when there is no detail.
std::string status_line(const CaseResult& result);
// status_line, then the captured output on the following lines.
std::string check_output(const CaseResult& result);

// "rendered on llvmpipe (LLVM 15.0.6, 256 bits)", or by lab where the labs' goldens came from different renderers:
// "lab01: llvmpipe (...); lab05: ...".
std::string golden_renderers_text(const GradeReport& report);

// 5 -> "5", 2.5 -> "2.5", 1/3 -> "0.33": points as a person writes them.
std::string format_points(double points);
// printf-style "%.*f".
std::string fixed(double value, int digits);

// The first line that mentions an error, else the first non-blank line, else "".
std::string first_error_line(std::string_view log);

// A lab's diagnosis in words for the student, one line each: the known mistakes that explain its failing cases ("one
// known mistake explains 10 of your 10 failing cases:", then "L01-T1: <what it says> (sheet: <section>)" per mistake),
// the failing cases none explains with the command that compares them, and the TODOs not started.
std::vector<std::string> diagnosis_lines(const LabDiagnosis& diagnosis);
// The part of a diagnosis a student may see whatever the run diagnosed: the public cases' (by the report's rows), the
// mistakes that explain one of them; a hidden case is never named.
LabDiagnosis student_diagnosis(const LabDiagnosis& diagnosis, const GradeReport& report);

// RFC 4648 base64 with padding.
std::string base64(std::string_view bytes);

// Labs in the order results name them, then labs that only have a build.
std::vector<std::string> lab_order(const GradeReport& report);
// The build of a lab, or nullptr when the report has none.
const LabBuild* find_build(const GradeReport& report, const std::string& lab);

}  // namespace gsv
