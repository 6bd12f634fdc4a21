#pragma once
// Runs one lab binary as a separate process with a wall-clock timeout (SIGKILL: an endless loop in a
// shader on llvmpipe dies no other way) and its output captured and capped.
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

struct ProcessResult {
    int exit_code = -1;      // valid when !signaled && !timed_out
    int signal = 0;          // the signal that ended it, 0 if none
    bool timed_out = false;
    bool failed_to_start = false;
    std::string output;      // stdout and stderr together, capped
    double seconds = 0;
};

struct ProcessLimits {
    std::chrono::milliseconds timeout{60000};
    std::size_t max_output_bytes = 64 * 1024;
};

// `environment` adds or overrides NAME=VALUE entries of the inherited environment.
ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& working_dir,
                          const ProcessLimits& limits, const std::vector<std::string>& environment = {});

}  // namespace gsv
