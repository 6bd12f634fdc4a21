#include "common/shader/compile_log.h"

#include "common/core/trimmed.h"
#include "common/shader/reference_compiler.h"

#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace gsv {
namespace {

struct LogLocation {
    int source_string;
    int line;
    std::string message;  // "error: ..." as the driver wrote it after the location
};

// The location formats of the drivers students meet: Mesa, NVIDIA, and glslang (also AMD, Apple, Intel).
std::optional<LogLocation> parse_log_line(const std::string& line) {
    static const std::regex mesa(R"(^\s*(\d+):(\d+)\(\d+\):\s*(.*)$)");
    static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
    static const std::regex glslang(R"(^\s*(ERROR|WARNING):\s*(\d+):(\d+):\s*(.*)$)");
    std::smatch m;
    try {
        if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nvidia))
            return LogLocation{std::stoi(m[1]), std::stoi(m[2]), m[3]};
        if (std::regex_match(line, m, glslang)) {
            const std::string severity = m[1] == "ERROR" ? "error" : "warning";
            return LogLocation{std::stoi(m[2]), std::stoi(m[3]), severity + ": " + m[4].str()};
        }
    } catch (const std::out_of_range&) {
        // A number too large for int cannot name one of our source strings; leave the line alone.
    }
    return std::nullopt;
}

// Where glslangValidator places the first error of `source`, when it is in a file (not the generated header).
std::optional<LogLocation> placed_by_reference_compiler(const ShaderSource& source, ShaderStage stage) {
    const std::optional<std::string> log = reference_compiler_log(source.text, stage);
    if (!log) return std::nullopt;
    std::istringstream in(*log);
    for (std::string line; std::getline(in, line);)
        if (std::optional<LogLocation> at = parse_log_line(line);
            at && at->source_string > 0 && static_cast<std::size_t>(at->source_string) < source.files.size())
            return at;
    return std::nullopt;
}

}  // namespace

std::string translate_compile_log(const std::string& log, const ShaderSource& source, ShaderStage stage) {
    std::string translated;
    std::optional<std::optional<LogLocation>> placed;  // asked at most once
    std::istringstream in(log);
    std::string line;
    bool first = true;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (!first) translated += "\n";
        first = false;
        std::optional<LogLocation> at = parse_log_line(line);
        if (!at || at->source_string < 0 || static_cast<std::size_t>(at->source_string) >= source.files.size()) {
            translated += line;
            continue;
        }
        std::string note;
        if (at->source_string == 0 && at->line > kGeneratedHeaderLineOffset) {
            at->line -= kGeneratedHeaderLineOffset;
        } else if (at->source_string == 0 && at->line != 1) {
            if (!placed) placed = placed_by_reference_compiler(source, stage);
            if (*placed) {
                at->source_string = (*placed)->source_string;
                at->line = (*placed)->line;
                note = " (placed by glslangValidator: the driver named no file)";
            } else {
                at->source_string = source.main_file_index;
                note = " (the driver named no file: the main file's line)";
            }
        }
        translated += source.files[static_cast<std::size_t>(at->source_string)] + ":" + std::to_string(at->line) +
                      ": " + trimmed(at->message) + note;
        const std::string quoted = trimmed(source.file_line_text(at->source_string, at->line));
        if (!quoted.empty()) translated += "\n    " + quoted;
    }
    if (!log.empty() && log.back() == '\n') translated += "\n";
    return translated;
}

}  // namespace gsv
