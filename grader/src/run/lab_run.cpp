#include "grader/src/run/lab_run.h"

#include "common/app/exit_status.h"
#include "common/core/error.h"
#include "grader/src/run/lab_serve.h"
#include "grader/src/run/render_conversation.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <set>
#include <unistd.h>

namespace fs = std::filesystem;

namespace gsv {
namespace {

std::string last_line(const std::string& text) {
    std::size_t end = text.find_last_not_of('\n');
    if (end == std::string::npos) return "";
    const std::size_t begin = text.rfind('\n', end);
    return text.substr(begin == std::string::npos ? 0 : begin + 1, end - (begin == std::string::npos ? 0 : begin + 1) + 1);
}

std::string line_with(const std::string& text, const std::string& what) {
    const auto at = text.find(what);
    if (at == std::string::npos) return "";
    const auto begin = text.rfind('\n', at);
    const auto from = begin == std::string::npos ? 0 : begin + 1;
    return text.substr(from, text.find('\n', at) - from);
}

std::string mib(std::uint64_t bytes) { return std::to_string((bytes + (1u << 19)) >> 20) + " MiB"; }

}  // namespace

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n == 0 ? 0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string as_student_sees(std::string text, const fs::path& student_kit) {
    const std::string root = student_kit.string() + "/";
    for (auto at = text.find(root); at != std::string::npos; at = text.find(root, at)) text.erase(at, root.size());
    return text;
}

CaseStatus classify(const ProcessResult& r, std::string& detail) {
    if (!r.cleanup_error.empty()) { detail = "grader: " + r.cleanup_error; return CaseStatus::Error; }
    if (!r.sandbox_error.empty()) { detail = r.sandbox_error; return CaseStatus::Error; }
    if (r.failed_to_start) { detail = "the lab binary could not be started"; return CaseStatus::MissingBinary; }
    if (r.timed_out) { detail = "killed after the time limit (an endless loop, or far too much work per frame?)"; return CaseStatus::Timeout; }
    if (r.flooded) { detail = "killed after printing " + std::to_string(r.output_bytes / 1024) + " KiB (print less per frame)"; return CaseStatus::OutputFlood; }
    if (!r.refused.empty()) { detail = "hand-in refused: " + r.refused; return CaseStatus::Refused; }
    if (r.folder_full) {
        detail = "wrote too much: " + mib(r.folder.bytes) + " in " + std::to_string(r.folder.files) + " files and folders; the working folder holds " +
                 mib(r.folder_limit_bytes) + " in " + std::to_string(r.folder_limit_files);
        return CaseStatus::WroteTooMuch;
    }
    const bool out_of_memory = r.output.find("bad_alloc") != std::string::npos ||
                               r.output.find("Cannot allocate memory") != std::string::npos ||
                               r.output.find("out of memory") != std::string::npos;
    if (r.signal == SIGXCPU) { detail = "killed at the CPU time limit"; return CaseStatus::Timeout; }
    if (r.signal == SIGXFSZ) { detail = "killed for writing a file over the size limit"; return CaseStatus::OutputFlood; }
    if (out_of_memory && (r.signal != 0 || r.exit_code != 0)) {
        detail = "ran out of memory at the grader's limit (an allocation that never stops?)";
        return CaseStatus::MemoryLimit;
    }
    if (r.signal != 0) {
        detail = std::string("crashed with signal ") + std::to_string(r.signal) + " (" + strsignal(r.signal) + ")";
        return CaseStatus::Crash;
    }
    // kExitError and kExitUsage: what the output says, below.
    switch (r.exit_code) {
    case kExitOk: return CaseStatus::Passed;
    case kExitUnsupported: detail = last_line(r.output); return CaseStatus::Unsupported;
    case kExitNonFinite: detail = "NaN or Inf in the image"; return CaseStatus::NonFinite;
    default: break;
    }
    if (const std::string line = line_with(r.output, "shader compile error"); !line.empty()) {
        // The located message ("file:line: error: ...") follows the line naming the program's main file.
        const auto after = r.output.find('\n', r.output.find(line));
        const std::string located = after == std::string::npos ? "" : r.output.substr(after + 1, r.output.find('\n', after + 1) - after - 1);
        detail = located.find("error") != std::string::npos ? located : line;
        return CaseStatus::ShaderCompileError;
    }
    if (const std::string line = line_with(r.output, "shader link error"); !line.empty()) {
        detail = line;
        return CaseStatus::ShaderLinkError;
    }
    detail = last_line(r.output);
    return CaseStatus::Error;
}

std::vector<std::string> LabRunner::environment() const {
    std::vector<std::string> out = extra_environment;
    if (!root.empty()) out.push_back("GSV_ROOT=" + root.string());
    return out;
}

LabRun LabRunner::render(const std::string& binary, const LabCases& lab, const GradeCase& c, const ProcessLimits& limits,
                         const std::vector<std::vector<std::string>>* challenges) const {
    const fs::path exe = bin_dir / binary;
    if (!fs::exists(exe)) {
        LabRun run;
        run.status = CaseStatus::MissingBinary;
        run.detail = "no binary " + exe.string() + " (did the lab build?)";
        return run;
    }
    const RenderRequest request = render_request(lab, c, profile, challenges);
    if (served && served->binary() == binary) return served->render(*this, lab, request, limits);
    std::vector<std::string> argv{exe.string()};
    for (auto& a : request.command_line()) argv.push_back(std::move(a));
    RenderConversation conversation(request);
    ProcessLimits with_handin = limits;
    with_handin.handin = &conversation;
    with_handin.private_folder = true;
    return rendered(run_process(argv, {}, with_handin, environment()), conversation, lab, request);
}

}  // namespace gsv
