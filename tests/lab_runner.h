#pragma once
// Runs the built lab binaries the way a student, the grader or CI would.
#include "common/core/error.h"
#include "common/image/image.h"
#include "common/image/image_compare.h"
#include "common/io/json.h"
#include "grader/src/run/process.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace gsv::test {

inline std::filesystem::path bin_dir() { return std::filesystem::path(GSV_BINARY_DIR) / "bin"; }

// A lab of the build's list (cmake/lab_list.cmake: the kit's folders solutions/labNN_name/, and each one's lab.json).
struct LabEntry {
    std::string id, dir;      // "lab05", "lab05_particles"
    std::string needs_gl;     // "4.1", or "4.3" for a lab that macOS's OpenGL cannot run
    bool needs_gl43() const { return needs_gl != "4.1"; }
};

// Where the list is: build/labs.json, written at configure time and read when the tests run, so a lab added recompiles
// no test. GSV_LAB_LIST names another (a scratch kit's list: what its tests would be).
inline std::filesystem::path lab_list_file() {
    const char* other = std::getenv("GSV_LAB_LIST");
    return other && *other ? std::filesystem::path(other) : std::filesystem::path(GSV_BINARY_DIR) / "labs.json";
}

// The build's labs, in order; throws gsv::Error naming the file when it cannot be read.
inline const std::vector<LabEntry>& lab_list() {
    static const std::vector<LabEntry> labs = [] {
        std::vector<LabEntry> list;
        const Json file = read_json_file(lab_list_file());  // kept: a range-for would not keep a temporary's member
        for (const Json& lab : file.array_at("labs").as_array())
            list.push_back({lab.string_at("id"), lab.string_at("dir"), lab.string_at("needs_gl")});
        return list;
    }();
    return labs;
}

// Every lab the build has ("lab01", ...).
inline std::vector<std::string> all_labs() {
    std::vector<std::string> labs;
    for (const LabEntry& lab : lab_list()) labs.push_back(lab.id);
    return labs;
}

// The labs macOS's OpenGL 4.1 core profile runs: every lab whose lab.json asks for no more.
inline std::vector<std::string> labs_on_gl41() {
    std::vector<std::string> labs;
    for (const LabEntry& lab : lab_list())
        if (!lab.needs_gl43()) labs.push_back(lab.id);
    return labs;
}

// A rule every lab is held to, its number as tests/lab_rules.json states it (the one place it is stated): "public_cases"
// is at least 8 public cases a lab, say. Throws gsv::Error for a rule the file does not state with a number.
inline int lab_rule(const std::string& name) {
    const std::filesystem::path file = std::filesystem::path(GSV_SOURCE_ROOT) / "tests" / "lab_rules.json";
    const Json rules = read_json_file(file);
    for (const Json& rule : rules.array_at("rules").as_array())
        if (rule.string_at("name") == name && rule.contains("least")) return static_cast<int>(rule.number_at("least"));
    throw Error(file.string() + ": no rule '" + name + "' with a number (\"least\")");
}

struct LabRun {
    ProcessResult process;
    std::filesystem::path png, json;
    int exit_code() const { return process.exit_code; }
};

// `binary` is e.g. "lab01_solution"; `args` follow it.
inline LabRun run_lab(const std::string& binary, std::vector<std::string> args, const std::filesystem::path& dir,
                      const std::vector<std::string>& environment = {}) {
    std::vector<std::string> argv{(bin_dir() / binary).string()};
    argv.insert(argv.end(), args.begin(), args.end());
    LabRun run;
    ProcessLimits limits;
    limits.timeout = std::chrono::milliseconds(120000);
    run.process = run_process(argv, dir, limits, environment);
    return run;
}

// Renders one image headless; returns the run (png/json set to the files it should have written).
inline LabRun render(const std::string& binary, const std::vector<std::string>& settings,
                     const std::filesystem::path& dir, const std::string& name,
                     std::vector<std::string> extra_args = {}, const std::vector<std::string>& environment = {}) {
    std::vector<std::string> args{"render", "--size", "128x128", "--frames", "1", "--warmup", "0",
                                  "--out", (dir / (name + ".png")).string()};
    for (const auto& s : settings) {
        args.push_back("--set");
        args.push_back(s);
    }
    args.insert(args.end(), extra_args.begin(), extra_args.end());
    LabRun run = run_lab(binary, args, dir, environment);
    run.png = dir / (name + ".png");
    run.json = dir / (name + ".json");
    return run;
}

using gsv::not_done_pixels;

// The lines the program printed that mention an error (everything but the context description).
inline std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const auto end = text.find('\n', start);
        lines.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return lines;
}

}  // namespace gsv::test
