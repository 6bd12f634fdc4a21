#pragma once
// The grader's side of one child process, as run_process (to its end) and ServedProcess (a request at a time) run it:
// started behind the walls with its output pipe, its report channel (what the sandbox's own processes say, never
// student code: sandbox.h) and its hand-in socket; read until a condition holds, it ends, or it is killed (at a
// deadline, for a flood of output, for a refused hand-in); then reaped, with what is left to learn about how it ended.
// Internal to grader/src/run/.
#include "common/io/temporary_folder.h"
#include "grader/src/run/process.h"

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace gsv {

// A descriptor of the grader's: close-on-exec, and numbered 10 or above, so that the child can move its own to
// 0-3 without one overwriting another, whatever the grader had open.
class Fd {
public:
    Fd() = default;
    explicit Fd(int fd);
    Fd(Fd&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
    Fd& operator=(Fd&& o) noexcept;
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() { reset(); }
    int get() const { return fd_; }
    void reset();

private:
    int fd_ = -1;
};

// What it printed past the output cap, said at the end of its output.
void note_cut_output(ProcessResult& result);

class HandinReader;  // handin_reader.h

class ChildProcess {
public:
    using Clock = std::chrono::steady_clock;

    // Starts `argv` as run_process describes (process.h); `served`: its sandbox's first process answers the grader's
    // commands while it runs (SandboxPlan::answers_commands). Throws gsv::Error when the grader cannot make its pipes;
    // a fork that fails is result.failed_to_start.
    ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& working_dir, const ProcessLimits& limits,
                 const std::vector<std::string>& environment, bool served);
    ~ChildProcess();  // one still running is killed and reaped
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    enum class Pumped { Done, Ended, Killed };
    // Reads its output, report channel and hand-in until `done()` holds (Done), it has ended (Ended: reaped), or it is
    // killed (Killed): at `deadline` (result.timed_out), for printing more than the flood limit since
    // result.output_bytes was last cleared (result.flooded). What it hands in goes to `conversation`, whose refusal
    // kills it (result.refused; it then ends); with none, anything it hands in is refused.
    Pumped pump(HandinConversation* conversation, Clock::time_point deadline, const std::function<bool()>& done);
    // Once it has ended or been killed: reaped, and result says how it ended, what its sandbox reported, what its working
    // folder held (and the folder removed, where it was the grader's), and how long it ran.
    void finish();

    // Sends a message on its hand-in socket, returning when its writing began (seconds since the start). Throws
    // gsv::Error when the process does not read it.
    double send(const HandinTag& tag, const std::vector<std::uint8_t>& payload);
    // A command to its sandbox's first process (SandboxPlan::answers_commands).
    void command(char c);
    // Whatever is readable now on the hand-in socket goes to `conversation` (none: refused).
    void take_handin(HandinConversation* conversation);
    void kill_all();

    bool running() const { return pid_ > 0 && !reaped_ && !killed_; }
    double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
    Clock::time_point start() const { return start_; }
    // "paused" lines its sandbox's first process has said (answers to 'p'), the last with the folder's use.
    int paused() const { return paused_; }

    ProcessResult result;

private:
    void read_output();
    void read_report(bool to_the_end);
    void take_report_line(const std::string& line);

    const ProcessLimits limits_;
    bool sandboxed_ = false;
    std::optional<TemporaryFolder> host_folder_;
    Fd output_, report_, handin_;
    std::optional<SandboxPlan> plan_;
    Clock::time_point start_;
    pid_t pid_ = -1;
    int status_ = 0;
    bool reaped_ = false, killed_ = false, output_open_ = true, report_open_ = true;
    std::unique_ptr<HandinReader> reader_;
    std::string report_text_;
    int paused_ = 0;
};

}  // namespace gsv
