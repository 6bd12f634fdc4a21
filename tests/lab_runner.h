#pragma once
// Runs the built lab binaries the way a student, the grader or CI would.
#include "common/image/image.h"
#include "common/image/image_compare.h"
#include "common/io/json.h"
#include "grader/src/run/process.h"

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace gsv::test {

inline std::filesystem::path bin_dir() { return std::filesystem::path(GSV_BINARY_DIR) / "bin"; }

// Every lab the build has ("lab01", ...), from CMake's list.
inline std::vector<std::string> all_labs() {
    std::vector<std::string> labs;
    std::string list = GSV_LABS;
    for (std::size_t start = 0; start < list.size();) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        if (comma > start) labs.push_back(list.substr(start, comma - start));
        start = comma + 1;
    }
    return labs;
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
