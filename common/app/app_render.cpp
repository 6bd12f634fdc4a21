// Headless render mode: one case to PNG, plus a JSON with timings and what GL really was, and beside them the
// arrays a lab hands in (common/io/data_array.h). Under the grader the same three go over its hand-in socket instead
// of into files, and the timed frames answer its challenges (common/io/handin.h).
#include "common/app/app_session.h"
#include "common/app/fetch_counter.h"
#include "common/core/error.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/image/image.h"
#include "common/image/image_compare.h"
#include "common/io/data_array.h"
#include "common/io/handin.h"
#include "common/io/json.h"
#include "common/io/output_folder.h"
#include "common/timing/timing.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

namespace gsv {

Json params_json(const Params& params) {
    Json out = Json::object();
    for (const auto& spec : params.specs()) out[spec.name] = params.get_text(spec.name);
    return out;
}

Json gl_json(const Context& context) {
    const ContextInfo& info = context.info();
    Json gl = Json::object();
    gl["renderer"] = info.renderer;
    gl["vendor"] = info.vendor;
    gl["version"] = info.version_string;
    gl["glsl"] = info.glsl_version_string;
    gl["profile"] = profile_name(info.profile);
    gl["backend"] = backend_name(info.backend);
    gl["requested"] = info.requested.str();
    gl["effective"] = context.effective_version().str();
    return gl;
}

// The lab's stated work: one entry per resource, as Lab::frame_work counts it.
Json work_json(const FrameWork& work) {
    Json items = Json::array();
    for (const auto& item : work.items) {
        Json entry = Json::object();
        entry["ceiling"] = item.ceiling_key();
        entry["kind"] = work_kind_name(item.kind);
        entry["path"] = shader_path_name(item.path);
        if (!item.texture.empty()) entry["texture"] = item.texture;
        entry["amount"] = item.amount;
        entry["what"] = item.what;
        items.push_back(entry);
    }
    Json out = Json::object();
    out["items"] = items;
    out["upper_bound"] = work.upper_bound;
    return out;
}

Json timing_json(const TimingStats& t, int warmup) {
    Json j = Json::object();
    j["median_ms"] = t.median_ms;
    j["min_ms"] = t.min_ms;
    j["max_ms"] = t.max_ms;
    j["mean_ms"] = t.mean_ms;
    j["frames"] = t.frames;
    j["warmup"] = warmup;
    return j;
}

// The report's list of the arrays; with files, where each is written beside the PNG.
Json write_arrays(const std::vector<DataArray>& arrays, const std::string& png, bool files) {
    Json listed = Json::array();
    for (const auto& a : arrays) {
        Json entry = Json::object();
        entry["name"] = a.name;
        if (files) entry["file"] = data_array_path(png, a.name).string();
        entry["components"] = a.components;
        entry["count"] = static_cast<double>(a.count());
        listed.push_back(entry);
    }
    return listed;
}

Readback read_back(const Framebuffer& target) {
    if (target.format() == ColorFormat::RGBA8) return {target.read_rgba8(), {}};
    const ImageF pixels = target.read_rgba32f();
    return {to_rgba8(pixels), float_stats(pixels)};
}

Framebuffer frame_target(Session& s, int width, int height) {
    if (Framebuffer::float_renderable()) return Framebuffer(width, height, ColorFormat::RGBA32F);
    if (!s.told_no_float_target)
        std::fprintf(stderr, "%s: this OpenGL ES driver lacks GL_EXT_color_buffer_float: frames render into RGBA8, so NaN "
                             "and Inf pixels are not detected (exit 4) and read back as black\n", s.info.id.c_str());
    s.told_no_float_target = true;
    return Framebuffer(width, height, ColorFormat::RGBA8);
}

namespace {

// The grader's timed frames: each drawn with the settings its challenge carries (over the case's) and answered
// with its pixels, until the grader says it has timed enough. The grader times each from its challenge to the
// last byte of the answer, and holds the answers against the reference's frames drawn with the same settings.
// They are drawn into an 8-bit target, which every profile reads back as bytes at the cost of a copy (llvmpipe
// converts a float target to bytes at about 24 ms a megapixel, which would weigh on every frame's time); `warmup`
// untimed frames into it first, so that nothing compiled for its format is charged to a timed frame.
void answer_challenges(Session& s, const HandinChannel& grader, const Frame& frame, int warmup) {
    Framebuffer target(frame.width, frame.height, ColorFormat::RGBA8);
    for (int i = 0; i < warmup; ++i) {
        target.bind();
        s.render_frame(frame);
    }
    glFinish();
    // What the case printed reaches the grader before it hears the case is done (a served lab goes on to the next).
    std::fflush(stdout);
    grader.send(kTagReady, {});
    while (const auto message = grader.receive()) {
        if (message->tag == kTagEnd) return;
        if (message->tag != kTagChallenge) throw Error("the grader sent a " + tag_name(message->tag) + " message, not a challenge");
        const HandinChallenge challenge = read_challenge_payload(message->payload);
        for (const auto& setting : challenge.settings) s.params.set_assignment(setting);
        if (auto error = s.sync_params()) throw Error(*error);
        target.bind();
        s.render_frame(frame);
        const Image pixels = target.read_rgba8();
        check_gl_error("drawing a timed frame");
        grader.send(kTagFrame, frame_payload(challenge.number, static_cast<std::uint32_t>(pixels.width),
                                             static_cast<std::uint32_t>(pixels.height), pixels.rgba));
    }
}

// What render mode hands the grader: the arrays, the image, then the report, which says the hand-in is complete.
void hand_in(const HandinChannel& grader, const Image& image, const std::vector<DataArray>& arrays, const Json& report) {
    for (const auto& a : arrays) grader.send(kTagArray, array_payload(a.name, static_cast<std::uint32_t>(a.components), a.values));
    grader.send(kTagImage, image_payload(static_cast<std::uint32_t>(image.width), static_cast<std::uint32_t>(image.height), image.rgba));
    const std::string text = report.dump(2);
    grader.send(kTagReport, std::vector<std::uint8_t>(text.begin(), text.end()));
}

}  // namespace

int run_render(Session& s) {
    // Under the grader nothing handed in is written to a file: the grader reads no path in a folder student code owns.
    const HandinChannel grader;
    std::string png = s.options.out;
    if (png.empty()) png = s.info.id + (s.options.case_name.empty() ? "" : "-" + s.options.case_name) + ".png";
    std::string json_path = s.options.json;
    if (json_path.empty()) json_path = std::filesystem::path(png).replace_extension(".json").string();
    if (!grader.active()) {
        prepare_output_file(png, "--out");
        prepare_output_file(json_path, "--json");
    }
    s.open(s.headless_backend());
    if (auto error = s.sync_params()) throw Error(*error);

    const int width = s.options.width, height = s.options.height;
    Framebuffer target = frame_target(s, width, height);
    const Frame frame{width, height, 0.0};
    // Under the grader the frame handed in is drawn once; the warm-up goes before the timed frames it asks for.
    const int warmup = grader.active() ? 0 : s.options.warmup >= 0 ? s.options.warmup : 1;
    const int frames = grader.active() ? 1 : s.options.frames > 0 ? s.options.frames : 3;
    // Each timed frame starts from a cleared target (render_frame), so the image read back is the last frame's own.
    const TimingStats timing = time_frames([&] {
        target.bind();
        s.render_frame(frame);
    }, warmup, frames);
    check_gl_error("rendering the frame");

    // The instrumented build (GSV_COUNT_FETCHES): one more frame, its lookups and primitives counted, held beside the
    // work the lab states for it. Not under the grader, whose frames are the student's.
    std::optional<FetchCounts> counted;
    if (fetch_count_define() && !grader.active()) {
        FetchCounter counter;
        counter.reset_and_bind();
        target.bind();
        s.render_frame(frame);
        counted = counter.read();
    }
    const FrameWork work = s.lab->frame_work(frame);
    // Against this device's ceilings where gsv-ceilings has measured them (build/ceilings.json): what scripts/kit
    // bench's roofline table reads.
    std::optional<Roofline> bound;
    if (const auto ceilings = cached_ceilings(s.executable, s.context->info().renderer)) bound = roofline(work, *ceilings);

    const Readback shot = read_back(target);
    const Image& image = shot.image;
    const FloatStats& stats = shot.stats;

    // The legend after the timed frames and before anything else draws: it describes the frame read back.
    const Image handed = s.options.legend ? with_lab_legend(s, image) : image;
    // After the last timed frame, so what is handed in is what the image shows. Only when asked: a million
    // particles are 32 MiB that a student's render does not need.
    const std::vector<DataArray> arrays = s.options.arrays ? s.lab->readback(*s.kit) : std::vector<DataArray>{};
    check_gl_error("reading back the lab's arrays");
    check_data_arrays(arrays);
    const Json listed = write_arrays(arrays, png, !grader.active());
    std::vector<std::filesystem::path> debug_images;
    if (s.options.debug_images && !grader.active())
        debug_images = s.lab->write_debug_images(*s.kit, std::filesystem::path(png).replace_extension().string() + "-debug");

    Json report = Json::object();
    report["lab"] = s.info.id;
    report["variant"] = s.variant;
    report["case"] = s.options.case_name;
    report["width"] = width;
    report["height"] = height;
    if (!grader.active()) report["image"] = png;
    report["params"] = params_json(s.params);
    report["timing"] = timing_json(timing, warmup);
    report["gl"] = gl_json(*s.context);
    if (!work.empty()) report["work"] = work_json(work);
    if (bound) {
        Json r = Json::object();
        r["bound_ms"] = bound->bound_ms;
        r["median_bound_ms"] = bound->median_bound_ms;
        r["fraction"] = bound->fraction(timing.median_ms);
        r["limiter"] = bound->limiter;
        r["upper_bound"] = bound->upper_bound;
        // The work whose resource has no ceiling measured: its time is left out of the bound.
        Json unmeasured = Json::array();
        for (const auto& key : bound->unmeasured) unmeasured.push_back(key);
        r["unmeasured"] = unmeasured;
        report["roofline"] = r;
    }
    if (counted) {
        Json c = Json::object();
        c["2d"] = static_cast<double>(counted->texture_2d);
        c["3d"] = static_cast<double>(counted->texture_3d);
        c["2d_array"] = static_cast<double>(counted->texture_2d_array);
        report["fetches_counted"] = c;
        report["primitives_counted"] = static_cast<double>(counted->primitives);
    }
    report["float_target"] = target.format() == ColorFormat::RGBA32F;  // false: NaN and Inf could not be counted
    report["nan_pixels"] = static_cast<double>(stats.nan_count);
    report["inf_pixels"] = static_cast<double>(stats.inf_count);
    report["blank"] = is_blank(image);
    if (s.options.legend) report["legend"] = true;  // the PNG is wider than width: the legend's panel is beside it
    if (!arrays.empty()) report["arrays"] = listed;
    if (grader.active()) {
        hand_in(grader, handed, arrays, report);
    } else {
        write_png(png, handed);
        for (const auto& a : arrays) write_f32_file(data_array_path(png, a.name), a.values);
        std::ofstream out(json_path);
        if (!out || !(out << report.dump(2) << "\n")) throw Error("cannot write '" + json_path + "'");
        std::printf("%s: wrote %s (%dx%d), median %.2f ms/frame over %d frames%s\n", s.info.id.c_str(), png.c_str(), width,
                    height, timing.median_ms, timing.frames,
                    bound ? (": " + bound->describe(timing.median_ms)).c_str() : "");
        for (const auto& file : debug_images) std::printf("%s: wrote %s\n", s.info.id.c_str(), file.string().c_str());
        for (const auto& a : arrays)
            std::printf("%s: wrote %s (%zu x %d floats)\n", s.info.id.c_str(), data_array_path(png, a.name).string().c_str(),
                        a.count(), a.components);
    }
    if (shot.non_finite()) {
        std::fprintf(stderr, "%s: the image has %ld NaN and %ld Inf pixel values (painted magenta%s%s)\n",
                     s.info.id.c_str(), stats.nan_count, stats.inf_count, grader.active() ? "" : " in ",
                     grader.active() ? "" : png.c_str());
        return kExitNonFinite;
    }
    if (grader.active()) answer_challenges(s, grader, frame, std::max(s.options.warmup, 0));
    return kExitOk;
}

}  // namespace gsv
