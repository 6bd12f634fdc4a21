#pragma once
// What sets each LMS's file apart (grader/README.md, "Grades out to the LMS", cites where each rule comes from): the
// columns that name a student, how a grade column is headed so that it fills an existing assignment, whether a
// feedback column is taken, and how fields are quoted and delimited.
#include "grader/src/lms/lms_export.h"
#include "grader/src/lms/lms_roster.h"

#include <string>
#include <vector>

namespace gsv {

// Throws gsv::Error naming the roster (and the line) where it lacks what `lms` needs to know a student: a column, or a
// row's value in it.
void check_roster_for(Lms lms, const Roster& roster);
// The columns that name a student, as the LMS heads them, and one student's cells under them.
std::vector<std::string> identity_header(Lms lms, const Roster& roster);
std::vector<std::string> identity_cells(Lms lms, const Roster& roster, const RosterStudent& student);
// What must name one student only: two roster rows with one `key` are one LMS student.
struct IdentityKey {
    std::string what;   // "SIS Login ID", "e-mail", ...
    std::string key;    // what is compared: the value, or for Moodle's e-mails the value without case
    std::string value;  // as the roster has it
};
std::vector<IdentityKey> identity_keys(Lms lms, const RosterStudent& student);

// Throws gsv::Error where `column` cannot fill an existing assignment of `lms` (Blackboard without a column id, an id
// for Moodle, a Canvas name that reads as an id); adds a line to `notes` where it may not (Canvas by name only).
void check_column_for(Lms lms, const GradeColumn& column, std::vector<std::string>& notes);
// Canvas "NAME (ID)" (or "NAME"), Moodle "NAME", Blackboard "NAME [Total Pts: MAX Score] |ID".
std::string grade_heading(Lms lms, const GradeColumn& column, double max_points);
// Moodle's feedback column beside its grade, "NAME (Feedback)"; Canvas's gradebook import and Blackboard's upload take
// none.
bool takes_feedback(Lms lms);
std::string feedback_heading(const GradeColumn& column);

// The file: Canvas and Moodle comma-separated, RFC 4180 (quoted where a field holds a comma, a quote or a line break);
// Blackboard tab-separated with every field quoted. Lines end in CRLF.
std::string table_text(Lms lms, const std::vector<std::vector<std::string>>& rows);
// Where the file goes without --to: <lms>-grades.csv, Blackboard's <lms>-grades.txt (its tab-delimited kind).
std::string default_file_name(Lms lms);

}  // namespace gsv
