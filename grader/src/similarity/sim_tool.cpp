#include "grader/src/similarity/sim_tool.h"

#include "common/core/error.h"
#include "grader/src/report/report_format.h"
#include "grader/src/run/process.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace gsv {

fs::path find_sim(SimLanguage language) {
    const std::string name = language == SimLanguage::C ? "sim_c" : "sim_c++";
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        if (dir.empty()) continue;
        const fs::path candidate = fs::path(dir) / name;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    throw Error("no " + name + " on PATH: " + kSimInstall);
}

SimOutput read_sim_output(const std::string& text) {
    static const std::regex file_line(R"(^File (\S+): (\d+) tokens?,.*$)");
    static const std::regex unreadable(R"(^File (.+): >>>> cannot open <<<<\s*$)");
    static const std::regex run_line(R"(^(\S+): line (\d+)-(\d+)\s*\|(\S+): line (\d+)-(\d+)\s*\[(\d+)\]\s*$)");
    SimOutput out;
    std::istringstream in(text);
    std::smatch m;
    for (std::string line; std::getline(in, line);) {
        if (std::regex_match(line, m, unreadable)) throw Error("similarity-tester could not open '" + m[1].str() + "'");
        if (std::regex_match(line, m, file_line)) {
            out.tokens_of[m[1]] = std::stoi(m[2]);
        } else if (std::regex_match(line, m, run_line)) {
            SimRun r;
            r.file_a = m[1];
            r.a_first = std::stoi(m[2]);
            r.a_last = std::stoi(m[3]);
            r.file_b = m[4];
            r.b_first = std::stoi(m[5]);
            r.b_last = std::stoi(m[6]);
            r.tokens = std::stoi(m[7]);
            out.runs.push_back(r);
        }
    }
    return out;
}

SimOutput run_sim(SimLanguage language, const std::vector<std::string>& options, const std::vector<std::string>& new_files,
                  const std::vector<std::string>& old_files, const fs::path& working_dir) {
    // SIM writes its report with -o; what it prints is only its complaints.
    const std::string report = "sim-output.txt";
    std::vector<std::string> argv{find_sim(language).string(), "-o", report};
    argv.insert(argv.end(), options.begin(), options.end());
    argv.insert(argv.end(), new_files.begin(), new_files.end());
    if (!old_files.empty()) {
        argv.push_back("/");
        argv.insert(argv.end(), old_files.begin(), old_files.end());
    }
    ProcessLimits limits;
    limits.timeout = std::chrono::minutes(10);
    const ProcessResult run = run_process(argv, working_dir, limits);
    if (run.failed_to_start || run.timed_out || run.signal != 0 || run.exit_code != 0)
        throw Error(argv.front() + " failed" + (run.timed_out ? " (timed out)" : "") + ": " + one_line(run.output, 300));
    std::ifstream in(working_dir / report);
    if (!in) throw Error(argv.front() + " wrote no report in " + working_dir.string() + ": " + one_line(run.output, 300));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    std::error_code ignored;
    fs::remove(working_dir / report, ignored);
    return read_sim_output(text);
}

}  // namespace gsv
