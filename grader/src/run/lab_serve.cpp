#include "grader/src/run/lab_serve.h"

#include "grader/src/run/render_conversation.h"
#include "grader/src/run/served_process.h"

namespace gsv {
namespace {

// Whether a failure could have come of the earlier cases in its process rather than of the case alone.
bool could_be_earlier_cases(const LabRun& run) {
    return !run.process.timed_out && !run.process.flooded && run.status != CaseStatus::Refused;
}

}  // namespace

ServedLab::ServedLab(std::string binary) : binary_(std::move(binary)) {}

ServedLab::~ServedLab() = default;

LabRun ServedLab::render(const LabRunner& runner, const LabCases& lab, const RenderRequest& request, const ProcessLimits& limits) {
    // The CPU-time limit is the process's (sandbox.h: the timeout times the cores, a backstop to it): a process that has
    // been busy half a timeout makes way for a fresh one rather than run into it in a later case.
    if (process_ && process_->busy_seconds() > 0.5 * std::chrono::duration<double>(limits.timeout).count()) process_.reset();
    const bool fresh = !process_ || !process_->running() || process_->answered() == 0;
    LabRun run = render_once(runner, lab, request, limits);
    run.after_other_cases = !fresh;
    if (run.status == CaseStatus::Passed) return run;
    process_.reset();
    if (fresh || !could_be_earlier_cases(run)) return run;
    run = render_once(runner, lab, request, limits);
    if (run.status != CaseStatus::Passed) process_.reset();
    return run;
}

LabRun ServedLab::render_once(const LabRunner& runner, const LabCases& lab, const RenderRequest& request, const ProcessLimits& limits) {
    if (!process_ || !process_->running()) {
        std::vector<std::string> argv{(runner.bin_dir / binary_).string(), "render", "--serve"};
        if (request.profile != Profile::Core) argv.insert(argv.end(), {"--profile", profile_name(request.profile)});
        ProcessLimits served = limits;
        served.private_folder = true;
        process_ = std::make_unique<ServedProcess>(argv, served, runner.environment());
        ++started_;
    }
    RenderConversation conversation(request);
    return rendered(process_->request(conversation, kTagCase, case_payload(request.served())), conversation, lab, request);
}

}  // namespace gsv
