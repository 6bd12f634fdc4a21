#include "grader/src/run/process.h"

#include "grader/src/run/child_process.h"

namespace gsv {

ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& working_dir,
                          const ProcessLimits& limits, const std::vector<std::string>& environment) {
    ChildProcess child(argv, working_dir, limits, environment, false);
    if (!child.running()) return child.result;
    child.pump(limits.handin, child.start() + limits.timeout, {});
    child.finish();
    return child.result;
}

}  // namespace gsv
