#pragma once
// A process that answers one request after another on its hand-in socket (a lab in `render --serve` mode:
// common/io/handin.h), behind exactly run_process's walls (process.h, sandbox.h). It says DONE when it waits for its
// first request, which is sent only then: what it hands in before is refused, not taken for an answer. Each request has a deadline of its
// own, timed from the request (the first from the start, which it includes), and its own output, flood limit and
// hand-in. Between requests nothing of a sandboxed one runs: its namespace's first process stops every process in it
// and measures its working folder (SandboxPlan::answers_commands), and anything handed in while no request is open
// is refused; so no case sees another's settings before it is asked, and nothing of the student's runs while the
// grader judges, the reference renders or anything is timed.
#include "grader/src/run/process.h"

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace gsv {

class ChildProcess;

class ServedProcess {
public:
    // Starts `argv` (throws gsv::Error where the grader cannot make its pipes). `limits.handin` is unused: each
    // request brings its conversation; `limits.timeout` is each request's unless it gives its own.
    ServedProcess(const std::vector<std::string>& argv, const ProcessLimits& limits, const std::vector<std::string>& environment);
    ~ServedProcess();  // ends it: END, a moment to exit, then killed
    ServedProcess(const ServedProcess&) = delete;
    ServedProcess& operator=(const ServedProcess&) = delete;

    // Sends `tag` and `payload` and lets `conversation` answer the process until it says the request is answered
    // (HandinConversation::answered), the process ends, or it is killed: at the deadline, for a flood of output, for
    // what it hands in. The result is this request's: its output, time and hand-in, and how the process ended where it
    // did (then it serves no more); an answered request is exit code 0, with the working folder as measured after it.
    ProcessResult request(HandinConversation& conversation, const HandinTag& tag, const std::vector<std::uint8_t>& payload);

    bool running() const;
    int answered() const { return answered_; }  // requests answered so far
    double busy_seconds() const { return busy_seconds_; }  // the requests' time so far, its start included

private:
    // Stops it between requests (a sandboxed one: every process of its namespace) and learns its folder's use.
    bool pause(std::chrono::steady_clock::time_point deadline);

    std::unique_ptr<ChildProcess> child_;
    const std::chrono::milliseconds timeout_;
    bool stoppable_ = false;  // its sandbox answers commands: pause and resume
    int answered_ = 0;
    double busy_seconds_ = 0;
};

}  // namespace gsv
