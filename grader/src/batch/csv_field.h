#pragma once
// One field of a CSV row as RFC 4180 writes it: quoted where it holds a comma, a quote or a line break, its quotes
// doubled. The class files (class.csv, class-cases.csv, history.csv, class-mistakes.csv) all write through it, and
// read back through csv_record.
#include <string>
#include <vector>

namespace gsv {

inline std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

// The fields of one CSV record that stands on one line, as RFC 4180 quotes them: a quoted field's doubled quotes are
// one quote, a CR outside quotes (a CRLF file's) is dropped. `closed`, when given, is set false where a quote is left
// open at the end of the line (a field with a line break in it, which no file read this way holds).
inline std::vector<std::string> csv_record(const std::string& line, bool* closed = nullptr) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                fields.back() += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                fields.back() += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields.emplace_back();
        } else if (c != '\r') {
            fields.back() += c;
        }
    }
    if (closed) *closed = !quoted;
    return fields;
}

}  // namespace gsv
