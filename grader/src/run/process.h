#pragma once
// Runs one lab binary as a separate process: a wall-clock timeout (SIGKILL: an endless loop in a shader
// on llvmpipe dies no other way), output captured and capped, a flood of output killed, and for student
// code the sandbox (sandbox.h), a clean environment and a working folder of its own.
//
// The process starts with nothing of the grader's: stdin is /dev/null, it leads a session of its own with no
// controlling terminal, and its only descriptors are 0-2 (and 3, the hand-in socket, where asked); every
// descriptor the grader makes is close-on-exec, and the child closes whatever else it inherited, so no thread's
// pipe leaks into another thread's child. What a lab hands in comes over the hand-in socket (common/io/handin.h),
// never from a file in a folder student code owns.
#include "common/io/folder_tree.h"
#include "common/io/handin.h"
#include "grader/src/run/sandbox.h"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gsv {

// The grader's side of a lab's hand-in socket while the lab runs.
class HandinConversation {
public:
    virtual ~HandinConversation() = default;
    // The most pixels an image or frame message may have in this run: a larger one is refused from its header.
    virtual std::uint64_t max_image_pixels() const = 0;
    // Sends a message to the lab; returns when its writing began, in seconds since the process started.
    using Reply = std::function<double(const HandinTag&, const std::vector<std::uint8_t>&)>;
    // A whole message, arrived at `t` (seconds since the start). Throw gsv::Error to refuse what the lab sent:
    // the process is killed, and the text is ProcessResult::refused.
    virtual void received(HandinMessage message, double t, const Reply& reply) = 0;
    // A message's header, with the payload size it declares, before the payload is read (or memory is set aside for
    // it): throw gsv::Error to refuse a message not wanted now or over what this render may take in all.
    virtual void announced(const HandinTag&, std::uint32_t /*declared_bytes*/) {}
    // A served process (served_process.h): whether the lab has said all this request asks for, so that the process
    // waits for the next one. run_process asks nothing of it: its process runs to its end.
    virtual bool answered() const { return false; }
};

struct ProcessResult {
    int exit_code = -1;      // valid when !signaled && !timed_out
    int signal = 0;          // the signal that ended it, 0 if none
    bool timed_out = false;
    bool failed_to_start = false;
    bool flooded = false;    // killed for printing more than ProcessLimits::flood_bytes
    std::string output;      // stdout and stderr together, capped
    std::size_t output_bytes = 0;  // all it printed, kept or not
    std::string sandbox_error;     // the sandbox could not be entered; the program did not run
    std::string refused;           // killed for what it sent on the hand-in socket, and why
    std::uint64_t handin_bytes = 0;  // all it sent there
    double seconds = 0;
    // A private working folder (ProcessLimits::private_folder): what it held when the process ended, whether it
    // was full (a sandbox limit reached), and the limits.
    FolderUse folder;
    bool folder_full = false;
    std::uint64_t folder_limit_bytes = 0, folder_limit_files = 0;
    std::string cleanup_error;     // the grader could not remove it: said, never ignored
};

struct ProcessLimits {
    std::chrono::milliseconds timeout{60000};
    std::size_t max_output_bytes = 64 * 1024;
    std::size_t flood_bytes = 16 * 1024 * 1024;
    // Student code: set both. The environment is then cleaned to what GL needs (see process.cpp).
    const SandboxPolicy* sandbox = nullptr;
    const SandboxSupport* support = nullptr;
    // A hand-in socket for the program (fd 3, named in $GSV_HANDIN_FD), and who answers on it.
    HandinConversation* handin = nullptr;
    std::uint64_t max_handin_bytes = 1ull << 30;  // more than this in all is refused
    // A working folder made for this process and gone after it (the `working_dir` argument is then unused): inside
    // the walls a tmpfs with the policy's folder limits, which leaves nothing on the host; without namespaces a
    // temporary folder of the grader's, measured against the same limits and removed.
    bool private_folder = false;
};

// `environment` adds or overrides NAME=VALUE entries.
ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& working_dir,
                          const ProcessLimits& limits, const std::vector<std::string>& environment = {});

}  // namespace gsv
