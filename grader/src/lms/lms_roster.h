#pragma once
// The roster `gsv-grade export` maps a batch's submissions to an LMS's students by (grader/README.md, "Grades out to
// the LMS"): a CSV file whose first row names its columns, one student a row. `submission` is the folder in the batch
// (GitHub Classroom names each folder by the student's login); the others are what one LMS or another knows the student
// by, so one roster can serve all three.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace gsv {

// The columns a roster may have: `submission`, then Canvas's (student, id, sis_user_id, sis_login_id, section), Moodle's
// (email, idnumber) and Blackboard's (username, last_name, first_name).
extern const std::vector<std::string> kRosterColumns;

struct RosterStudent {
    std::string submission;
    std::map<std::string, std::string> fields;  // the roster's other columns, by name; "" where a row leaves one empty
    int line = 0;                               // its line in the file, for messages

    // The value in `column`, "" where the roster has no such column or the row leaves it empty.
    std::string value(const std::string& column) const;
};

struct Roster {
    std::filesystem::path file;
    std::vector<std::string> columns;  // as the header has them
    std::vector<RosterStudent> students;  // in the file's order

    bool has(const std::string& column) const;
    // "roster.csv:7", for a message about a row.
    std::string where(const RosterStudent& student) const;
};

// Reads a roster: UTF-8 (a byte-order mark is skipped), RFC 4180 quoting, one record a line, blank lines and lines that
// start with '#' skipped, spaces around a value dropped. Throws gsv::Error with one line naming the file and line: a
// missing or unreadable file, a header column not in kRosterColumns or named twice, no `submission` column, a row with
// more or fewer fields than the header, an empty submission, a quote left open, text that is not UTF-8, or a tab or
// other control character (no LMS file can carry one safely).
Roster read_roster_csv(const std::filesystem::path& file);

}  // namespace gsv
