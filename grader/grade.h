#pragma once
// Grades the labs of one kit tree: each case is rendered headless by the student's binary in its own
// process and compared with the reference (rendered live by <lab>_solution when it is there, else the
// committed golden image).
#include "grader/cases.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

enum class CaseStatus { Passed, WrongImage, NonFinite, MissingBinary, ShaderError, Crash, Timeout, MissingOutput,
                        Unsupported, Error, ReferenceFailed };
const char* status_name(CaseStatus status);

struct CaseResult {
    std::string lab, name, todo, visibility;
    double points = 0, max_points = 0;
    CaseStatus status = CaseStatus::Error;
    std::string detail;  // one line for the table; output holds the rest
    std::string output;  // what helps the student: compiler messages, where the image differs
    std::string reference;  // "live" or "golden"
    double seconds = 0;
};

struct GradeOptions {
    std::filesystem::path kit_root;     // where grader/cases and grader/golden are
    std::filesystem::path bin_dir;      // where the lab binaries are
    std::filesystem::path out_dir;      // images and reports
    std::vector<std::string> labs;      // empty: every lab with a case file
    bool self_check = false;            // never use a live reference, even when present
    bool update_goldens = false;        // render the references into grader/golden instead of grading
    double timeout_s = 0;               // per-process limit; 0: the case file's timeout_s
};

std::vector<CaseResult> grade(const GradeOptions& options, void (*progress)(const CaseResult&) = nullptr);
std::string score_table(const std::vector<CaseResult>& results);
std::string results_json(const std::vector<CaseResult>& results);  // Gradescope-shaped results.json

}  // namespace gsv
