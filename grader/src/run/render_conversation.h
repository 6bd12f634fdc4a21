#pragma once
// One render of a case as the grader asks a lab for it, the same whether the lab runs for that case alone
// (`render` with the case on its command line: lab_run.cpp) or serves case after case (`render --serve`, the case
// as a request: lab_serve.cpp), and the grader's side of the hand-in that answers it. Internal to grader/src/run/.
#include "grader/src/run/lab_run.h"

#include "common/io/handin.h"
#include "common/io/json.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gsv {

// What one render asks of the lab: the case's settings at the lab's size, or for a timed run at its timing size after
// its warm-up, one frame per challenge.
struct RenderRequest {
    int width = 0, height = 0, warmup = 0;
    bool arrays = false;
    Profile profile = Profile::Core;
    std::optional<GlVersion> gl;  // on ES: the case's version, where it names one
    std::vector<std::string> settings;
    const std::vector<std::vector<std::string>>* challenges = nullptr;
    const GlFeature* feature = nullptr;  // the case's "feature": a run whose context lacks it says so (LabRun::lacks)

    bool timed() const { return challenges != nullptr; }
    // The one-case command line after the binary: render --size WxH --frames 1 --warmup N [--arrays] [--profile P]
    // [--gl X.Y] --set name=value...
    std::vector<std::string> command_line() const;
    // The same as a served lab's request (common/io/handin.h).
    HandinCase served() const;
};
RenderRequest render_request(const LabCases& lab, const GradeCase& c, Profile profile,
                             const std::vector<std::vector<std::string>>* challenges);

// The grader's side of one render: the hand-in (arrays, image, report: the report last), then, once the lab says it
// is warm, for a timed run one challenge at a time, each answered by its frame. Anything out of that order, or
// malformed, is refused.
class RenderConversation : public HandinConversation {
public:
    explicit RenderConversation(const RenderRequest& request)
        : width_(request.width), height_(request.height), arrays_asked_(request.arrays), challenges_(request.challenges) {}

    std::uint64_t max_image_pixels() const override { return std::uint64_t(width_) * std::uint64_t(height_); }
    // Every cap of the hand-in, from the header, before the payload is read: arrays only where the case asks for them,
    // at most kMaxArrays of them and kMaxArrayFloats floats in all (the bytes they may take, names and counts
    // included); one image, before one report; a timed frame only once asked for. So what the grader holds of one
    // render is bounded whatever the lab sends (grader/README.md, "Arrays").
    void announced(const HandinTag& tag, std::uint32_t declared_bytes) override;
    void received(HandinMessage message, double t, const Reply& reply) override;
    // Served: the hand-in, the ready that follows it, every frame asked for, the grader's END, then the lab's DONE.
    bool answered() const override { return done_; }

    bool handed_in() const { return report_.has_value(); }
    // The frame time the lab reports for its own frame: for the benchmark's breakdown only, never for a grade.
    double reported_frame_ms() const;
    // GL_RENDERER as the lab reports it: one line of at most 200 bytes, whatever a student's lab wrote there.
    std::string renderer() const;
    // Where the lab's report says its context (profile, the version it held to) lacks `feature`: the line saying so
    // ("needs compute shaders ..., which OpenGL has from 4.3; this run holds to 4.1 ..."); empty where it has it.
    std::string lacks(const GlFeature& feature) const;
    bool answered_all() const { return !challenges_ || frames.size() == challenges_->size(); }

    std::optional<Image> image;
    std::vector<DataArray> arrays;
    std::vector<Image> frames;
    std::vector<double> frame_ms;

private:
    // The next challenge, or the end.
    void ask(const Reply& reply);

    int width_, height_;
    bool arrays_asked_;
    const std::vector<std::vector<std::string>>* challenges_;
    std::size_t arrays_announced_ = 0;
    std::uint64_t array_bytes_announced_ = 0, array_floats_ = 0;
    std::optional<Json> report_;
    std::set<std::string> names_;
    bool ready_ = false, asked_ = false, done_ = false;
    double asked_at_ = 0;
};

// The run as the grader grades it: how the process ended (classify), then what it handed in (an image of the asked
// size, the arrays, every timed frame asked for).
LabRun rendered(ProcessResult process, RenderConversation& conversation, const LabCases& lab, const RenderRequest& request);

}  // namespace gsv
