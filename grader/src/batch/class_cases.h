#pragma once
// A batch's grades case by case (issue 42): every graded submission's rows of its report.json as one table, the same
// summed per TODO and per lab, and a history that each run of the batch appends to, row by row, with the old points,
// the new and why they changed. An instructor answers "why did my grade change?" from history.csv, and pivots the
// class from class-cases.csv without reading a report.json each.
#include "grader/src/batch/batch.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

// One graded check of one submission: a case's image or timing row, as its report.json has it.
struct ClassCaseRow {
    std::string submission, lab, todo, check, kind, status;
    double points = 0, max_points = 0;
};

// The rows of every graded entry, read from <out_dir>/<name>/report.json, in class order, then the report's order.
// A graded entry without one is said on stderr and has no rows; a report that does not read throws gsv::Error naming it.
std::vector<ClassCaseRow> class_case_rows(const std::filesystem::path& out_dir, const std::vector<BatchEntry>& entries);

// class-cases.csv: submission,lab,todo,check,kind,status,points,max_points.
std::string class_cases_csv(const std::vector<ClassCaseRow>& rows);
// class-todos.csv: submission,lab,todo,points,max_points (a TODO's cases summed).
std::string class_todos_csv(const std::vector<ClassCaseRow>& rows);
// The rows a class-cases.csv holds; none where it is missing (a batch's first run). Throws naming a malformed line.
std::vector<ClassCaseRow> read_class_cases_csv(const std::filesystem::path& file);

// Each row whose points differ from `before` (or that is new, or gone), as history.csv lines:
// when,submission,lab,check,kind,old_points,new_points,max_points,why. `why` comes from the entry: the labs this run
// graded ("lab02 graded again: its inputs changed"), or a first grading.
std::string history_lines(const std::vector<ClassCaseRow>& before, const std::vector<ClassCaseRow>& now,
                          const std::vector<BatchEntry>& entries, const std::string& when);
inline constexpr const char* kHistoryHeader = "when,submission,lab,check,kind,old_points,new_points,max_points,why\n";

// Writes class-cases.csv and class-todos.csv into out_dir and appends this run's changes to history.csv (made with
// its header on the first run). Returns the rows written.
std::vector<ClassCaseRow> write_class_cases(const std::filesystem::path& out_dir, const std::vector<BatchEntry>& entries);

}  // namespace gsv
