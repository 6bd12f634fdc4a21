#include "grader/src/lms/lms_dialect.h"

#include "common/core/error.h"
#include "grader/src/batch/csv_field.h"
#include "grader/src/report/report_format.h"

#include <algorithm>
#include <cctype>
#include <regex>

namespace gsv {
namespace {

// Each row of the roster has a value in `column`, or the error names the first that has not.
void require_values(const Roster& roster, const std::string& column, const std::string& why) {
    for (const RosterStudent& s : roster.students)
        if (s.value(column).empty()) throw Error(roster.where(s) + ": '" + s.submission + "' has no " + column + " (" + why + ")");
}

void require_column(const Roster& roster, const std::string& column, Lms lms, const std::string& why) {
    if (!roster.has(column))
        throw Error(roster.file.string() + ":1: --lms " + lms_name(lms) + " needs the column '" + column + "' (" + why + ")");
}

// Canvas's Student cell: the roster's `student`, or "Last, First" as Canvas's own export writes names.
std::string canvas_student(const RosterStudent& s) {
    if (!s.value("student").empty()) return s.value("student");
    if (s.value("last_name").empty() || s.value("first_name").empty()) return s.value("last_name") + s.value("first_name");
    return s.value("last_name") + ", " + s.value("first_name");
}

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

}  // namespace

void check_roster_for(Lms lms, const Roster& roster) {
    switch (lms) {
    case Lms::Canvas:
        require_column(roster, "sis_login_id", lms, "Canvas's SIS Login ID, which with Student and Section names a student");
        if (!roster.has("student") && !(roster.has("last_name") && roster.has("first_name")))
            throw Error(roster.file.string() + ":1: --lms canvas needs the column 'student' (or 'last_name' and 'first_name'): "
                        "Canvas's Student column");
        require_values(roster, "sis_login_id", "Canvas's SIS Login ID");
        for (const RosterStudent& s : roster.students)
            if (canvas_student(s).empty()) throw Error(roster.where(s) + ": '" + s.submission + "' has no student name");
        break;
    case Lms::Moodle:
        if (!roster.has("email") && !roster.has("idnumber"))
            throw Error(roster.file.string() + ":1: --lms moodle needs the column 'email' or 'idnumber': what Moodle's import "
                        "maps a row to a user by");
        // Moodle stops the whole import at a row whose user it cannot find, so every row needs what it is mapped by.
        for (const char* column : {"email", "idnumber"})
            if (roster.has(column)) require_values(roster, column, "Moodle refuses a whole file for one row it cannot map");
        break;
    case Lms::Blackboard:
        require_column(roster, "username", lms, "Blackboard's Username, the key of every Grade Center row");
        require_values(roster, "username", "Blackboard's Username");
        break;
    }
}

std::vector<std::string> identity_header(Lms lms, const Roster& roster) {
    switch (lms) {
    case Lms::Canvas: return {"Student", "ID", "SIS User ID", "SIS Login ID", "Section"};
    case Lms::Moodle: {
        std::vector<std::string> header;
        if (roster.has("email")) header.push_back("Email address");
        if (roster.has("idnumber")) header.push_back("ID number");
        return header;
    }
    case Lms::Blackboard: return {"Last Name", "First Name", "Username"};
    }
    return {};
}

std::vector<std::string> identity_cells(Lms lms, const Roster& roster, const RosterStudent& s) {
    switch (lms) {
    case Lms::Canvas: return {canvas_student(s), s.value("id"), s.value("sis_user_id"), s.value("sis_login_id"), s.value("section")};
    case Lms::Moodle: {
        std::vector<std::string> cells;
        if (roster.has("email")) cells.push_back(s.value("email"));
        if (roster.has("idnumber")) cells.push_back(s.value("idnumber"));
        return cells;
    }
    case Lms::Blackboard: return {s.value("last_name"), s.value("first_name"), s.value("username")};
    }
    return {};
}

std::vector<IdentityKey> identity_keys(Lms lms, const RosterStudent& s) {
    std::vector<IdentityKey> keys;
    const auto key = [&](const char* what, const std::string& column) {
        if (!s.value(column).empty()) keys.push_back({what, s.value(column), s.value(column)});
    };
    switch (lms) {
    case Lms::Canvas:
        key("SIS Login ID", "sis_login_id");
        key("Canvas ID", "id");
        key("SIS User ID", "sis_user_id");
        break;
    case Lms::Moodle:
        // Two e-mails that differ in case only are one address to a mail server but two to Moodle's import, which
        // compares them exactly: one of the two is not the e-mail Moodle holds. Compared without case here.
        if (!s.value("email").empty()) keys.push_back({"e-mail", lowercase(s.value("email")), s.value("email")});
        key("ID number", "idnumber");
        break;
    case Lms::Blackboard: key("Username", "username"); break;
    }
    return keys;
}

void check_column_for(Lms lms, const GradeColumn& column, std::vector<std::string>& notes) {
    const std::string named = "column '" + column.what + "' ('" + column.name + "')";
    switch (lms) {
    case Lms::Canvas:
        if (column.id.empty()) {
            // Canvas reads a trailing "(digits)" of a heading as the assignment id.
            if (std::regex_search(column.name, std::regex("\\([0-9]+\\)$")))
                throw Error(named + ": Canvas would read its last '(...)' as an assignment id: give the id (NAME|ID)");
            notes.push_back(named + " has no assignment id: Canvas fills the assignment of exactly that name, or makes a new one");
        }
        // instructure/canvas-lms#2134: an upload leaves out a column whose assignment's name has "final" in it.
        if (lowercase(column.name).find("final") != std::string::npos)
            notes.push_back(named + ": Canvas has been seen to ignore uploads to an assignment whose name holds 'final' "
                            "(canvas-lms issue 2134): check the import's preview");
        break;
    case Lms::Moodle:
        if (!column.id.empty())
            throw Error(named + ": Moodle's import maps each column to a grade item in its form, by name; it takes no id");
        break;
    case Lms::Blackboard:
        if (column.id.empty())
            throw Error(named + " needs its Grade Center column id (NAME|ID, the number after '|' in a downloaded heading): "
                        "without one Blackboard makes a new text column worth 0 points, left out of its totals");
        if (column.name.find('|') != std::string::npos) throw Error(named + ": a '|' in the name would end it before the column id");
        break;
    }
}

std::string grade_heading(Lms lms, const GradeColumn& column, double max_points) {
    switch (lms) {
    case Lms::Canvas: return column.id.empty() ? column.name : column.name + " (" + column.id + ")";
    case Lms::Moodle: return column.name;
    case Lms::Blackboard: return column.name + " [Total Pts: " + format_points(max_points) + " Score] |" + column.id;
    }
    return column.name;
}

bool takes_feedback(Lms lms) { return lms == Lms::Moodle; }

std::string feedback_heading(const GradeColumn& column) { return column.name + " (Feedback)"; }

std::string table_text(Lms lms, const std::vector<std::vector<std::string>>& rows) {
    std::string text;
    for (const auto& row : rows) {
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (lms == Lms::Blackboard) {
                // Every field quoted, as Blackboard's own downloads are; a quote inside doubled.
                std::string quoted = "\"";
                for (const char c : row[i]) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
                text += (i ? "\t" : "") + quoted + "\"";
            } else {
                text += (i ? "," : "") + csv_field(row[i]);
            }
        }
        text += "\r\n";
    }
    return text;
}

std::string default_file_name(Lms lms) { return std::string(lms_name(lms)) + (lms == Lms::Blackboard ? "-grades.txt" : "-grades.csv"); }

}  // namespace gsv
