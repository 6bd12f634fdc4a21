#include "grader/src/run/served_process.h"

#include "common/core/error.h"
#include "grader/src/run/child_process.h"

namespace gsv {
namespace {

// A served process's first words: DONE, waiting for its first request. Anything before it was handed in unasked.
class FirstWords : public HandinConversation {
public:
    std::uint64_t max_image_pixels() const override { return 0; }
    void announced(const HandinTag& tag, std::uint32_t) override {
        if (tag != kTagDone || said_) throw Error("handed in a " + tag_name(tag) + " message before the grader asked for a case");
    }
    void received(HandinMessage, double, const Reply&) override { said_ = true; }
    bool answered() const override { return said_; }

private:
    bool said_ = false;
};

}  // namespace

ServedProcess::ServedProcess(const std::vector<std::string>& argv, const ProcessLimits& limits, const std::vector<std::string>& environment)
    : timeout_(limits.timeout) {
    ProcessLimits served = limits;
    served.handin = nullptr;
    child_ = std::make_unique<ChildProcess>(argv, std::filesystem::path(), served, environment, true);
    stoppable_ = limits.sandbox && limits.support && limits.sandbox->enabled && limits.support->allow_list();
}

ServedProcess::~ServedProcess() {
    if (!child_ || !child_->running()) return;
    try {
        if (stoppable_) child_->command('r');
        child_->send(kTagEnd, {});
        child_->pump(nullptr, std::chrono::steady_clock::now() + std::chrono::seconds(2), {});
    } catch (const Error&) {
        // Gone already, or not listening: the kill below ends it either way.
    }
    if (child_->running()) child_->kill_all();
    child_->finish();
}

bool ServedProcess::running() const { return child_ && child_->running(); }

bool ServedProcess::pause(std::chrono::steady_clock::time_point deadline) {
    if (!stoppable_) return child_->running();
    const int before = child_->paused();
    child_->command('p');
    const auto pumped = child_->pump(nullptr, deadline, [&] { return child_->paused() > before; });
    if (pumped != ChildProcess::Pumped::Done) return false;
    // Whatever reached the socket before every thread stopped: nothing was asked, so it is refused.
    child_->take_handin(nullptr);
    return child_->running();
}

ProcessResult ServedProcess::request(HandinConversation& conversation, const HandinTag& tag, const std::vector<std::uint8_t>& payload) {
    ChildProcess& child = *child_;
    const auto asked = std::chrono::steady_clock::now();
    // The first request's time includes the start, as a process of its own per request would.
    const auto from = answered_ == 0 ? child.start() : asked;
    const auto deadline = from + timeout_;
    // What the process printed before this request (its start, the last case's end) is this request's too: a case in a
    // process of its own would show it. Its hand-in and flood limit are this request's alone.
    child.result.handin_bytes = 0;
    child.result.output_bytes = child.result.output.size();
    bool ready = child.running();
    if (answered_ == 0) {
        FirstWords first;
        ready = child.pump(&first, deadline, [&] { return first.answered(); }) == ChildProcess::Pumped::Done && pause(deadline);
    }
    if (ready) {
        try {
            child.send(tag, payload);
        } catch (const Error& e) {
            child.result.refused = e.what();
            child.kill_all();
        }
    }
    if (ready && child.running()) {
        if (stoppable_) child.command('r');
        const auto pumped = child.pump(&conversation, deadline, [&] { return conversation.answered(); });
        // Stopped at once, whatever time the request had left: stopping takes the sandbox milliseconds.
        if (pumped == ChildProcess::Pumped::Done && pause(std::chrono::steady_clock::now() + std::chrono::seconds(10))) {
            ++answered_;
            ProcessResult result = child.result;
            result.exit_code = 0;
            result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
            busy_seconds_ += result.seconds;
            note_cut_output(result);
            child.result.output.clear();
            child.result.output_bytes = 0;
            return result;
        }
    }
    child.finish();
    ProcessResult result = child.result;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
    return result;
}

}  // namespace gsv
