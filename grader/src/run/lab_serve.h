#pragma once
// One lab binary rendering a grading run's cases one after another in one process (`render --serve`), for one runner
// (the student's or the reference's) and one lab of one submission. Each case is a request on the hand-in socket
// (served_process.h), answered with exactly the hand-in a process of its own would give, from a fresh lab, session
// and GL context (common/app/app_serve.cpp). Any case that does not pass as a process (a crash, a timeout, a flood, a
// refused hand-in, a full working folder, an error exit) ends the process with that case's status as classify()
// gives it, and the next case starts another. A failure in a process that served earlier cases could come of what
// they left (its address space, its CPU time, its working folder: the walls count them per process), so the case
// is rendered once more in a fresh process, whose outcome stands; not a wall-clock timeout (timed from its own
// request), a flood (counted per request) or a refused hand-in, which are the case's own.
#include "grader/src/run/lab_run.h"

#include <memory>
#include <string>

namespace gsv {

class ServedProcess;
struct RenderRequest;

class ServedLab {
public:
    explicit ServedLab(std::string binary);
    ~ServedLab();  // ends the process
    ServedLab(const ServedLab&) = delete;
    ServedLab& operator=(const ServedLab&) = delete;

    const std::string& binary() const { return binary_; }
    // The case as LabRunner::render gives it (the runner's binary folder, root and profile; `limits` as for a process
    // of its own, whose timeout is each request's).
    LabRun render(const LabRunner& runner, const LabCases& lab, const RenderRequest& request, const ProcessLimits& limits);
    int processes_started() const { return started_; }

private:
    LabRun render_once(const LabRunner& runner, const LabCases& lab, const RenderRequest& request, const ProcessLimits& limits);

    std::string binary_;
    std::unique_ptr<ServedProcess> process_;
    int started_ = 0;
};

}  // namespace gsv
