#pragma once
// Running another program and waiting for it: the reference solution a `compare` renders with. The grader has its
// own sandboxed runner (grader/src/run/process.h); this one is for the kit's own binaries, trusted, with no limits.
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

struct ProgramExit {
    int code = 0;    // the exit status; -1 when it ended by a signal
    int signal = 0;  // the signal that ended it, 0 if none
    bool ok() const { return code == 0 && signal == 0; }
};

// Runs argv[0] (a path) with the rest as its arguments and waits for it. Its standard output and error go to
// `output` (created or truncated) where the platform allows (POSIX); on Windows they stay the caller's.
// Throws gsv::Error naming the program when it cannot be started.
ProgramExit run_program(const std::vector<std::string>& argv, const std::filesystem::path& output);

}  // namespace gsv
