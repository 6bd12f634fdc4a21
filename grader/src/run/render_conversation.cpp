#include "grader/src/run/render_conversation.h"

#include "common/context/context.h"
#include "common/core/error.h"
#include "grader/src/core/safe_text.h"

#include <algorithm>
#include <cmath>

namespace gsv {

std::vector<std::string> RenderRequest::command_line() const {
    // One frame handed in (after the warm-up, for a timed run); the timed frames are the challenges'.
    std::vector<std::string> argv{"render", "--size", std::to_string(width) + "x" + std::to_string(height), "--frames", "1",
                                  "--warmup", std::to_string(warmup)};
    if (arrays) argv.push_back("--arrays");
    if (profile != Profile::Core) argv.insert(argv.end(), {"--profile", profile_name(profile)});
    if (gl) argv.insert(argv.end(), {"--gl", gl->str()});
    for (const auto& s : settings) argv.insert(argv.end(), {"--set", s});
    return argv;
}

HandinCase RenderRequest::served() const {
    HandinCase c;
    c.width = static_cast<std::uint32_t>(width);
    c.height = static_cast<std::uint32_t>(height);
    c.warmup = static_cast<std::uint32_t>(warmup);
    c.arrays = arrays;
    if (gl) {
        c.gl_major = static_cast<std::uint32_t>(gl->major);
        c.gl_minor = static_cast<std::uint32_t>(gl->minor);
    }
    c.settings = settings;
    return c;
}

RenderRequest render_request(const LabCases& lab, const GradeCase& c, Profile profile,
                             const std::vector<std::vector<std::string>>* challenges) {
    RenderRequest r;
    const bool timed = challenges != nullptr;
    r.width = timed ? lab.timing_width : lab.width;
    r.height = timed ? lab.timing_height : lab.height;
    r.warmup = timed ? lab.timing_warmup : 0;
    r.arrays = lab.checks_arrays() && !timed;
    r.profile = profile;
    if (profile == Profile::Es && c.es_version) r.gl = *c.es_version;
    r.settings = c.settings;
    r.challenges = challenges;
    r.feature = c.feature;
    return r;
}

// The most bytes the arrays of one render may take on the socket: kMaxArrays headers and names, kMaxArrayFloats floats.
constexpr std::uint64_t kMaxArrayBytesInAll = kMaxArrays * (12 + kMaxArrayNameBytes) + 4 * kMaxArrayFloats;

void RenderConversation::announced(const HandinTag& tag, std::uint32_t declared_bytes) {
    if (tag == kTagArray) {
        if (!arrays_asked_) throw Error("handed in an array, which this case does not ask for (it checks no arrays)");
        if (report_) throw Error("handed in an array after its report");
        if (++arrays_announced_ > kMaxArrays) throw Error("handed in more than " + std::to_string(kMaxArrays) + " arrays");
        array_bytes_announced_ += declared_bytes;
        if (array_bytes_announced_ > kMaxArrayBytesInAll)
            throw Error("announced arrays of " + std::to_string(array_bytes_announced_) + " bytes in all, over the " +
                        std::to_string(kMaxArrayFloats) + " floats (" + std::to_string(kMaxArrayBytesInAll) +
                        " bytes with their names) a render may hand in");
    } else if (tag == kTagImage) {
        if (image || report_) throw Error("handed in a second image");
    } else if (tag == kTagReport) {
        if (report_) throw Error("handed in a second report");
        if (!image) throw Error("handed in its report before its image");
    } else if (tag == kTagFrame) {
        if (!asked_)
            throw Error("handed in a timed frame before the grader asked for it (the grader " +
                        (challenges_ && frames.size() < challenges_->size() ? "waits for frame " + std::to_string(frames.size())
                                                                             : std::string("asked for none")) +
                        "): frames are timed from the grader's request to their answer");
    }
}

void RenderConversation::received(HandinMessage message, double t, const Reply& reply) {
    const HandinTag& tag = message.tag;
    if (tag == kTagArray) {
        if (report_) throw Error("handed in an array after its report");
        HandinArray a = read_array_payload(message.payload);
        message.payload = {};  // the floats are in `a` now: one copy held, not two
        if (!names_.insert(a.name).second) throw Error("handed in array '" + a.name + "' twice");
        if (arrays.size() >= kMaxArrays) throw Error("handed in more than " + std::to_string(kMaxArrays) + " arrays");
        array_floats_ += a.values.size();
        if (array_floats_ > kMaxArrayFloats)
            throw Error("handed in more than the " + std::to_string(kMaxArrayFloats) + " floats in all a render may hand in (array '" +
                        a.name + "')");
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
    } else if (tag == kTagDone) {
        if (!ready_ || !answered_all() || done_)
            throw Error(done_ ? "said twice that its case was done" : "said its case was done before it had answered it");
        done_ = true;
    } else {
        throw Error("sent a " + tag_name(tag) + " message, which a lab does not send");
    }
}

double RenderConversation::reported_frame_ms() const {
    const Json* timing = report_ ? report_->find("timing") : nullptr;
    const Json* ms = timing && timing->is_object() ? timing->find("median_ms") : nullptr;
    return ms && ms->is_number() && std::isfinite(ms->as_number()) && ms->as_number() >= 0 ? std::min(ms->as_number(), 1e6) : 0;
}

std::string RenderConversation::renderer() const {
    const Json* gl = report_ ? report_->find("gl") : nullptr;
    const Json* name = gl && gl->is_object() ? gl->find("renderer") : nullptr;
    return name && name->is_string() ? one_line(name->as_string(), 200) : "";
}

std::string RenderConversation::lacks(const GlFeature& feature) const {
    const Json* gl = report_ ? report_->find("gl") : nullptr;
    const Json* profile = gl && gl->is_object() ? gl->find("profile") : nullptr;
    const Json* effective = gl && gl->is_object() ? gl->find("effective") : nullptr;
    if (!profile || !profile->is_string() || !effective || !effective->is_string()) return "";
    try {
        const Profile p = parse_profile(profile->as_string());
        const GlVersion held_to = parse_gl_version(effective->as_string(), p);
        return allows(feature, p, held_to) ? "" : missing_feature_message(feature, p, held_to);
    } catch (const Error&) {
        return "";  // a report the lab mangled: graded as any other run
    }
}

void RenderConversation::ask(const Reply& reply) {
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

LabRun rendered(ProcessResult process, RenderConversation& conversation, const LabCases& lab, const RenderRequest& request) {
    LabRun run;
    run.process = std::move(process);
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
    if (request.feature) run.lacks = conversation.lacks(*request.feature);
    if (run.image->width != request.width || run.image->height != request.height)
        run.detail = "the image is " + std::to_string(run.image->width) + "x" + std::to_string(run.image->height) + ", not " +
                     std::to_string(request.width) + "x" + std::to_string(request.height);
    if (lab.checks_arrays() && !request.timed()) run.arrays = std::move(conversation.arrays);
    if (request.timed()) {
        if (!conversation.answered_all()) {
            run.status = CaseStatus::Refused;
            run.detail = "hand-in refused: answered " + std::to_string(conversation.frames.size()) +
                         " of the " + std::to_string(request.challenges->size()) + " timed frames asked for";
            return run;
        }
        run.challenges = *request.challenges;
        run.frames = std::move(conversation.frames);
        run.frame_ms = std::move(conversation.frame_ms);
        run.median_ms = median(run.frame_ms);
    }
    return run;
}

}  // namespace gsv
