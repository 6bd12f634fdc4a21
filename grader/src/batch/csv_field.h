#pragma once
// One field of a CSV row as RFC 4180 writes it: quoted where it holds a comma, a quote or a line break, its quotes
// doubled. The class files (class.csv, class-cases.csv, history.csv, class-mistakes.csv) all write through it.
#include <string>

namespace gsv {

inline std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

}  // namespace gsv
