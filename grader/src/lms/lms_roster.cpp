#include "grader/src/lms/lms_roster.h"

#include "common/core/error.h"
#include "grader/src/batch/csv_field.h"
#include "grader/src/report/report_format.h"

#include <algorithm>
#include <fstream>

namespace fs = std::filesystem;

namespace gsv {

const std::vector<std::string> kRosterColumns{"submission", "student",  "id",       "sis_user_id", "sis_login_id", "section",
                                              "email",      "idnumber", "username", "last_name",   "first_name"};

namespace {

std::string trimmed(const std::string& text) {
    const auto first = text.find_first_not_of(' ');
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(' ') - first + 1);
}

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
    return text;
}

// Why `line` cannot be read as roster text, or "" where it can.
std::string text_fault(const std::string& line) {
    if (valid_utf8(line) != line) return "not UTF-8 (save the roster as CSV UTF-8)";
    for (const char c : line)
        if (static_cast<unsigned char>(c) < 0x20 && c != '\r')
            return c == '\t' ? "a tab (a roster is comma-separated, and no LMS file carries a tab in a value safely)"
                             : "a control character";
    return "";
}

}  // namespace

std::string RosterStudent::value(const std::string& column) const {
    const auto at = fields.find(column);
    return at == fields.end() ? "" : at->second;
}

bool Roster::has(const std::string& column) const { return std::find(columns.begin(), columns.end(), column) != columns.end(); }

std::string Roster::where(const RosterStudent& student) const { return file.string() + ":" + std::to_string(student.line); }

Roster read_roster_csv(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error("cannot read the roster '" + file.string() + "'");
    Roster roster;
    roster.file = file;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string at = file.string() + ":" + std::to_string(number) + ": ";
        // Excel's "CSV UTF-8" starts the file with a byte-order mark.
        if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
        if (const std::string fault = text_fault(line); !fault.empty()) throw Error(at + fault);
        if (trimmed(line).empty() || trimmed(line) == "\r" || line.rfind('#', 0) == 0) continue;
        bool closed = true;
        std::vector<std::string> fields = csv_record(line, &closed);
        if (!closed) throw Error(at + "a quote is left open (a value cannot hold a line break)");
        for (std::string& field : fields) field = trimmed(field);
        if (roster.columns.empty()) {
            for (const std::string& column : fields) {
                if (std::find(kRosterColumns.begin(), kRosterColumns.end(), column) == kRosterColumns.end())
                    throw Error(at + "unknown column '" + column + "' (a roster's columns: " + joined(kRosterColumns) + ")");
                if (roster.has(column)) throw Error(at + "column '" + column + "' named twice");
                roster.columns.push_back(column);
            }
            if (!roster.has("submission")) throw Error(at + "no 'submission' column (the folder of each student's work in the batch)");
            continue;
        }
        if (fields.size() != roster.columns.size())
            throw Error(at + std::to_string(fields.size()) + " fields, the header has " + std::to_string(roster.columns.size()));
        RosterStudent student;
        student.line = number;
        for (std::size_t i = 0; i < fields.size(); ++i) {
            if (roster.columns[i] == "submission")
                student.submission = fields[i];
            else
                student.fields[roster.columns[i]] = fields[i];
        }
        if (student.submission.empty()) throw Error(at + "no submission (the folder of this student's work in the batch)");
        roster.students.push_back(student);
    }
    if (roster.columns.empty()) throw Error(file.string() + ": empty: a roster needs a header row (submission,...) and a row a student");
    return roster;
}

}  // namespace gsv
