#include "grader/src/run/lab_run.h"

#include "common/app/exit_status.h"
#include "common/core/error.h"
#include "common/io/json.h"
#include "grader/src/report/report_format.h"

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

// The grader's side of one render: the hand-in (arrays, image, report: the report last), then, once the lab says it
// is warm, for a timed run one challenge at a time, each answered by its frame. Anything out of that order, or
// malformed, is refused.
class RenderConversation : public HandinConversation {
public:
    RenderConversation(int width, int height, const std::vector<std::vector<std::string>>* challenges)
        : width_(width), height_(height), challenges_(challenges) {}

    std::uint64_t max_image_pixels() const override { return std::uint64_t(width_) * std::uint64_t(height_); }

    void received(HandinMessage message, double t, const Reply& reply) override {
        const HandinTag& tag = message.tag;
        if (tag == kTagArray) {
            if (report_) throw Error("handed in an array after its report");
            HandinArray a = read_array_payload(message.payload);
            if (!names_.insert(a.name).second) throw Error("handed in array '" + a.name + "' twice");
            if (arrays.size() >= kMaxArrays) throw Error("handed in more than " + std::to_string(kMaxArrays) + " arrays");
            arrays.push_back({a.name, static_cast<int>(a.components), std::move(a.values)});
        } else if (tag == kTagImage) {
            if (image || report_) throw Error("handed in a second image");
            HandinImage i = read_image_payload(message.payload);
            image.emplace();
            image->width = static_cast<int>(i.width);
            image->height = static_cast<int>(i.height);
            image->rgba = std::move(i.rgba);
        } else if (tag == kTagReport) {
            if (report_) throw Error("handed in a second report");
            if (!image) throw Error("handed in its report before its image");
            report_ = parse_json(std::string(message.payload.begin(), message.payload.end()), "the lab's report");
            if (!challenges_) reply(kTagEnd, {});
        } else if (tag == kTagReady) {
            if (!report_ || ready_) throw Error("said it was ready for timed frames " + std::string(ready_ ? "twice" : "before its hand-in"));
            ready_ = true;
            if (challenges_) ask(reply);
        } else if (tag == kTagFrame) {
            HandinFrame f = read_frame_payload(message.payload);
            if (!asked_ || f.number != frames.size())
                throw Error("handed in timed frame " + std::to_string(f.number) + " before the grader asked for it (the grader " +
                            (asked_ ? "waits for frame " + std::to_string(frames.size()) : std::string("asked for none yet")) +
                            "): frames are timed from the grader's request to their answer");
            if (f.image.width != static_cast<std::uint32_t>(width_) || f.image.height != static_cast<std::uint32_t>(height_))
                throw Error("timed frame " + std::to_string(f.number) + " is " + std::to_string(f.image.width) + "x" +
                            std::to_string(f.image.height) + ", not " + std::to_string(width_) + "x" + std::to_string(height_));
            frame_ms.push_back(1000.0 * (t - asked_at_));
            Image frame;
            frame.width = width_;
            frame.height = height_;
            frame.rgba = std::move(f.image.rgba);
            frames.push_back(std::move(frame));
            ask(reply);
        } else {
            throw Error("sent a " + tag_name(tag) + " message, which a lab does not send");
        }
    }

    bool handed_in() const { return report_.has_value(); }
    // The frame time the lab reports for its own frame: for the benchmark's breakdown only, never for a grade.
    double reported_frame_ms() const {
        const Json* timing = report_ ? report_->find("timing") : nullptr;
        const Json* ms = timing && timing->is_object() ? timing->find("median_ms") : nullptr;
        return ms && ms->is_number() && std::isfinite(ms->as_number()) && ms->as_number() >= 0 ? std::min(ms->as_number(), 1e6) : 0;
    }
    // GL_RENDERER as the lab reports it: one line of at most 200 bytes, whatever a student's lab wrote there.
    std::string renderer() const {
        const Json* gl = report_ ? report_->find("gl") : nullptr;
        const Json* name = gl && gl->is_object() ? gl->find("renderer") : nullptr;
        return name && name->is_string() ? one_line(name->as_string(), 200) : "";
    }
    bool answered_all() const { return !challenges_ || frames.size() == challenges_->size(); }

    std::optional<Image> image;
    std::vector<DataArray> arrays;
    std::vector<Image> frames;
    std::vector<double> frame_ms;

private:
    // The next challenge, or the end.
    void ask(const Reply& reply) {
        if (!challenges_ || frames.size() == challenges_->size()) {
            asked_ = false;
            reply(kTagEnd, {});
            return;
        }
        const std::uint32_t number = static_cast<std::uint32_t>(frames.size());
        const std::vector<std::uint8_t> payload = challenge_payload({number, (*challenges_)[number]});
        asked_ = true;
        // Timed from just before the challenge is written: the lab cannot have begun the frame before that.
        asked_at_ = reply(kTagChallenge, payload);
    }

    int width_, height_;
    const std::vector<std::vector<std::string>>* challenges_;
    std::optional<Json> report_;
    std::set<std::string> names_;
    bool ready_ = false, asked_ = false;
    double asked_at_ = 0;
};

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

LabRun LabRunner::render(const std::string& binary, const LabCases& lab, const GradeCase& c, const ProcessLimits& limits,
                         const std::vector<std::vector<std::string>>* challenges) const {
    const bool timed = challenges != nullptr;
    const int width = timed ? lab.timing_width : lab.width, height = timed ? lab.timing_height : lab.height;
    LabRun run;
    const fs::path exe = bin_dir / binary;
    if (!fs::exists(exe)) {
        run.status = CaseStatus::MissingBinary;
        run.detail = "no binary " + exe.string() + " (did the lab build?)";
        return run;
    }
    // One frame handed in (after the warm-up, for a timed run); the timed frames are the challenges'.
    std::vector<std::string> argv{exe.string(), "render", "--size", std::to_string(width) + "x" + std::to_string(height),
                                  "--frames", "1", "--warmup", std::to_string(timed ? lab.timing_warmup : 0)};
    if (lab.checks_arrays() && !timed) argv.push_back("--arrays");
    if (profile != Profile::Core) argv.insert(argv.end(), {"--profile", profile_name(profile)});
    if (profile == Profile::Es && c.es_version) argv.insert(argv.end(), {"--gl", c.es_version->str()});
    for (const auto& s : c.settings) {
        argv.push_back("--set");
        argv.push_back(s);
    }
    std::vector<std::string> env;
    if (!root.empty()) env.push_back("GSV_ROOT=" + root.string());
    RenderConversation conversation(width, height, challenges);
    ProcessLimits with_handin = limits;
    with_handin.handin = &conversation;
    with_handin.private_folder = true;
    run.process = run_process(argv, {}, with_handin, env);
    run.status = classify(run.process, run.detail);
    if (run.status != CaseStatus::Passed) return run;
    if (!conversation.handed_in()) {
        run.status = CaseStatus::MissingOutput;
        run.detail = "the lab exited 0 but handed in no image and report (render mode hands them to the grader)";
        return run;
    }
    run.image = std::move(conversation.image);
    run.reported_ms = conversation.reported_frame_ms();
    run.renderer = conversation.renderer();
    if (run.image->width != width || run.image->height != height)
        run.detail = "the image is " + std::to_string(run.image->width) + "x" + std::to_string(run.image->height) + ", not " +
                     std::to_string(width) + "x" + std::to_string(height);
    if (lab.checks_arrays() && !timed) run.arrays = std::move(conversation.arrays);
    if (timed) {
        if (!conversation.answered_all()) {
            run.status = CaseStatus::Refused;
            run.detail = "hand-in refused: answered " + std::to_string(conversation.frames.size()) +
                         " of the " + std::to_string(challenges->size()) + " timed frames asked for";
            return run;
        }
        run.challenges = *challenges;
        run.frames = std::move(conversation.frames);
        run.frame_ms = std::move(conversation.frame_ms);
        run.median_ms = median(run.frame_ms);
    }
    return run;
}

}  // namespace gsv
