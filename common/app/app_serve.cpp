// render --serve: the grader's cases one after another in one process (common/io/handin.h). Process start, the
// loaded libraries and the EGL display are paid once; everything a case could leave to the next is made anew for
// each: the lab object (from its factory), its parameters (declared again, so at their defaults before the case's
// settings apply), the session, the GL context and with it every GL object. Each case then runs exactly as a one-case
// `render` would, its errors ending the process with the exit status that command would give.
#include "common/app/app_session.h"
#include "common/core/error.h"
#include "common/io/handin.h"

#include <cstdio>
#include <string>

namespace gsv {
namespace {

// What a one-case command line would hold: the served process's own options (profile, backend) with the case's.
// Throws gsv::Error, a usage error, for what that command line would refuse.
CliOptions case_options(const CliOptions& served, const HandinCase& request) {
    CliOptions o = served;
    o.serve = false;
    if (request.width < 1 || request.width > kMaxImageSide || request.height < 1 || request.height > kMaxImageSide)
        throw Error("a case of " + std::to_string(request.width) + "x" + std::to_string(request.height) + " pixels (each side 1.." +
                    std::to_string(kMaxImageSide) + ")");
    if (request.warmup > 100000) throw Error("a case with " + std::to_string(request.warmup) + " warm-up frames (0..100000)");
    o.width = static_cast<int>(request.width);
    o.height = static_cast<int>(request.height);
    o.size_given = true;
    o.frames = 1;
    o.warmup = static_cast<int>(request.warmup);
    o.arrays = request.arrays;
    o.assignments = request.settings;
    if (request.gl_major != 0 || request.gl_minor != 0)
        o.gl = parse_gl_version(std::to_string(request.gl_major) + "." + std::to_string(request.gl_minor), o.profile);
    return o;
}

int serve_case(const LabFactory& make_lab, const Session& started, const HandinCase& request) {
    Session session;
    std::string stage = "command line";
    return with_exit_status(session, stage, [&]() -> int {
        start_session(session, make_lab(), started.lab_dir.c_str(), started.variant.c_str(), started.executable);
        try {
            session.options = case_options(started.options, request);
            session.apply_command_line_settings();
        } catch (const Error& e) {
            std::fprintf(stderr, "%s: %s\n", session.info.id.c_str(), e.what());
            return kExitUsage;
        }
        stage = "start";
        session.keep_display = true;
        session.find_assets();
        return run_render(session);
    });
}

}  // namespace

int run_serve(const LabFactory& make_lab, const Session& started) {
    const HandinChannel grader;
    if (!grader.active())
        throw Error("render --serve renders the cases gsv-grade sends over its hand-in socket ($" + std::string(kHandinVariable) +
                    " is not set): run render without --serve");
    // Waiting for the first case: what this process sent before it (nothing, honestly) the grader refuses.
    grader.send(kTagDone, {});
    while (const auto message = grader.receive()) {
        if (message->tag == kTagEnd) return kExitOk;
        if (message->tag != kTagCase) throw Error("the grader sent a " + tag_name(message->tag) + " message, not a case");
        const int status = serve_case(make_lab, started, read_case_payload(message->payload));
        // A case that failed ends the process as its one-case run would have ended: the grader starts another.
        if (status != kExitOk) return status;
        std::fflush(stdout);
        grader.send(kTagDone, {});
    }
    return kExitOk;  // the grader closed its end
}

}  // namespace gsv
