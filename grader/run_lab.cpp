#include "grader/run_lab.h"

#include "common/core/error.h"
#include "common/io/json.h"
#include "grader/lab_arrays.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
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

// A working folder of its own, removed afterwards.
class ScratchDir {
public:
    ScratchDir() {
        std::string pattern = (fs::temp_directory_path() / "gsv-case-XXXXXX").string();
        if (!mkdtemp(pattern.data())) throw Error(std::string("cannot make a temporary folder: ") + std::strerror(errno));
        path_ = pattern;
    }
    ~ScratchDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

}  // namespace

double median_frame_ms(const std::vector<double>& marks, int frames) {
    if (marks.size() != static_cast<std::size_t>(frames) + 1)
        throw Error("the lab marked " + std::to_string(marks.empty() ? 0 : marks.size() - 1) + " timed frames, not " +
                    std::to_string(frames) + " (the grader times frames by the marks the framework writes)");
    std::vector<double> ms;
    for (std::size_t i = 1; i < marks.size(); ++i) ms.push_back(1000.0 * (marks[i] - marks[i - 1]));
    std::sort(ms.begin(), ms.end());
    const std::size_t n = ms.size();
    return n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
}

CaseStatus classify(const ProcessResult& r, std::string& detail) {
    if (!r.sandbox_error.empty()) { detail = r.sandbox_error; return CaseStatus::Error; }
    if (r.failed_to_start) { detail = "the lab binary could not be started"; return CaseStatus::MissingBinary; }
    if (r.timed_out) { detail = "killed after the time limit (an endless loop, or far too much work per frame?)"; return CaseStatus::Timeout; }
    if (r.flooded) { detail = "killed after printing " + std::to_string(r.output_bytes / 1024) + " KiB (print less per frame)"; return CaseStatus::OutputFlood; }
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
    switch (r.exit_code) {
    case 0: return CaseStatus::Passed;
    case 3: detail = last_line(r.output); return CaseStatus::Unsupported;
    case 4: detail = "NaN or Inf in the image"; return CaseStatus::NonFinite;
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

LabRun LabRunner::render(const std::string& binary, const LabCases& lab, const GradeCase& c, bool timed,
                         const ProcessLimits& limits) const {
    const int width = timed ? lab.timing_width : lab.width, height = timed ? lab.timing_height : lab.height;
    const int frames = timed ? lab.timing_frames : 1, warmup = timed ? lab.timing_warmup : 0;
    LabRun run;
    const fs::path exe = bin_dir / binary;
    if (!fs::exists(exe)) {
        run.status = CaseStatus::MissingBinary;
        run.detail = "no binary " + exe.string() + " (did the lab build?)";
        return run;
    }
    ScratchDir scratch;
    if (student && limits.support && limits.sandbox) hand_over(scratch.path(), *limits.sandbox, *limits.support);
    const fs::path png = scratch.path() / "out.png";
    const fs::path json = scratch.path() / "out.json";
    std::vector<std::string> argv{exe.string(), "render", "--size", std::to_string(width) + "x" + std::to_string(height),
                                  "--out", png.string(), "--json", json.string(),
                                  "--frames", std::to_string(frames), "--warmup", std::to_string(warmup)};
    if (lab.checks_arrays() && !timed) argv.push_back("--arrays");
    if (profile != Profile::Core) argv.insert(argv.end(), {"--profile", profile_name(profile)});
    if (profile == Profile::Es && c.es_version) argv.insert(argv.end(), {"--gl", c.es_version->str()});
    for (const auto& s : c.settings) {
        argv.push_back("--set");
        argv.push_back(s);
    }
    std::vector<std::string> env;
    if (!root.empty()) env.push_back("GSV_ROOT=" + root.string());
    ProcessLimits marked = limits;
    marked.frame_marks = true;
    run.process = run_process(argv, scratch.path(), marked, env);
    run.status = classify(run.process, run.detail);
    if (run.status != CaseStatus::Passed) return run;
    try {
        if (!fs::is_regular_file(png)) throw Error("the lab exited 0 but wrote no image");
        Image image = read_png(png);
        if (image.width != width || image.height != height)
            run.detail = "the image is " + std::to_string(image.width) + "x" + std::to_string(image.height) + ", not " +
                         std::to_string(width) + "x" + std::to_string(height);
        run.image = std::move(image);
        // The framework always writes its report; it lists the arrays a lab hands in.
        if (!fs::is_regular_file(json) || fs::file_size(json) > 1024 * 1024)
            throw Error("the lab wrote no valid JSON report beside its image");
        const Json report = read_json_file(json);
        run.median_ms = median_frame_ms(run.process.marks, frames);
        if (lab.checks_arrays() && !timed) run.arrays = read_lab_arrays(report, json, png);
    } catch (const Error& e) {
        run.status = CaseStatus::MissingOutput;
        run.detail = e.what();
    }
    return run;
}

}  // namespace gsv
