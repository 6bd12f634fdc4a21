#pragma once
// A batch's grades as the file an LMS imports (issue 42, item 2; grader/README.md, "Grades out to the LMS"): Canvas's
// gradebook CSV, Moodle's CSV grade import, Blackboard's Grade Center upload. Every student of the roster and every
// submission of the batch is written or named in a problem: none is dropped without a word.
#include "grader/src/batch/batch_record.h"
#include "grader/src/lms/lms_roster.h"

#include <string>
#include <vector>

namespace gsv {

enum class Lms { Canvas, Moodle, Blackboard };

// "canvas", "moodle" or "blackboard"; throws gsv::Error naming the text otherwise.
Lms parse_lms(const std::string& text);
const char* lms_name(Lms lms);

// One column of grades: the batch's total or one lab's points, under the LMS's assignment (Canvas), grade item (Moodle)
// or Grade Center column (Blackboard) it fills.
struct GradeColumn {
    std::string what;  // "total" or a lab of the batch ("lab01")
    std::string name;  // the assignment's name in the LMS
    std::string id;    // its id there (Canvas's assignment id, Blackboard's column id); "" where none is given
};

// --column WHAT=NAME or WHAT=NAME|ID (ID: digits at the end); throws gsv::Error naming the text.
GradeColumn parse_grade_column(const std::string& text);

struct LmsExportOptions {
    Lms lms = Lms::Canvas;
    std::vector<GradeColumn> columns;  // none: the total and every lab, each named by what it is ("total", "lab01")
    bool feedback = true;              // Moodle's feedback column beside each grade (the others import none)
    bool percent = false;              // each grade as a percentage of its maximum rather than points
    double moodle_grade_limit = 100;   // Moodle's gradepointmax: a grade above it makes Moodle refuse the whole file
    // Write the students that match even where others do not; the problems are listed all the same.
    bool allow_partial = false;
};

struct LmsExport {
    std::string text;                   // the file, byte for byte
    std::size_t rows = 0;               // students written
    std::vector<GradeColumn> columns;   // the columns written
    // One line each: a student or submission left out or written as 0, and why. Any one fails the export unless
    // allow_partial; a `blocking` one (a roster that names a student twice) fails it even then.
    std::vector<std::string> problems;
    bool blocking = false;
    std::vector<std::string> notes;     // said, but failing nothing: a column Canvas matches by name only
    bool written() const { return !blocking && (problems.empty() || allow_partial); }
    bool allow_partial = false;
};

// The LMS file for `record` (one batch, or shards merged: a single shard's record is refused) and its case rows.
// Throws gsv::Error with one line for what cannot make a file at all: a roster without the columns the LMS needs, a
// column naming a lab the batch has not got, a grade over Moodle's limit.
LmsExport export_grades(const BatchRecord& record, const std::vector<ClassCaseRow>& cases, const Roster& roster,
                        const LmsExportOptions& options);

// The text a student is shown beside a grade: each lab's points and the TODOs that lost points, one line
// ("lab01 12/18 (L01-T2 0/6, L01-T4 2/6); lab02 20/20"); only `lab`'s where one is named.
std::string feedback_text(const std::vector<ClassCaseRow>& cases, const std::string& submission, const std::string& lab = "");

}  // namespace gsv
