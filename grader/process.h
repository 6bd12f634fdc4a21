#pragma once
// Runs one lab binary as a separate process: a wall-clock timeout (SIGKILL: an endless loop in a shader
// on llvmpipe dies no other way), output captured and capped, a flood of output killed, and for student
// code the sandbox (sandbox.h), a clean environment and a working folder of its own.
#include "grader/sandbox.h"

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
    bool flooded = false;    // killed for printing more than ProcessLimits::flood_bytes
    std::string output;      // stdout and stderr together, capped
    std::size_t output_bytes = 0;  // all it printed, kept or not
    std::string sandbox_error;     // the sandbox could not be entered; the program did not run
    double seconds = 0;
    // With ProcessLimits::frame_marks: when each byte the program wrote to its frame-marks pipe arrived, in seconds
    // since it started, by the grader's clock.
    std::vector<double> marks;
};

struct ProcessLimits {
    std::chrono::milliseconds timeout{60000};
    std::size_t max_output_bytes = 64 * 1024;
    std::size_t flood_bytes = 16 * 1024 * 1024;
    // Student code: set both. The environment is then cleaned to what GL needs (see process.cpp).
    const SandboxPolicy* sandbox = nullptr;
    const SandboxSupport* support = nullptr;
    // Hand the program a pipe for frame marks (common/timing/frame_marks.h): fd 3, named in $GSV_FRAME_MARKS_FD.
    bool frame_marks = false;
};

// `environment` adds or overrides NAME=VALUE entries.
ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& working_dir,
                          const ProcessLimits& limits, const std::vector<std::string>& environment = {});

}  // namespace gsv
