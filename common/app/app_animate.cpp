// Animate mode: the lab's animated parameter stepped over its range, headless. Each frame is a PNG (to
// compare or put on a slide) and all of them one looping APNG (to play in a browser or a report).
#include "common/app/app_session.h"
#include "common/core/error.h"
#include "common/core/number_text.h"
#include "common/gl/gl.h"
#include "common/image/animation.h"
#include "common/io/output_folder.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace gsv {
namespace {

struct Axis {
    std::string name;
    double from = 0, to = 1;
    double min = 0, max = 1;  // the parameter's own range
};

Axis animation_axis(const Session& s) {
    const ParamSpec* spec = s.params.animation_axis();
    if (!spec) throw Error(s.info.id + " has no animated parameter to step (a lab marks one with .animated())");
    if (spec->type != ParamType::Float)
        throw Error(s.info.id + " marks '" + spec->name + "' as animated, but only a Float parameter can be");
    Axis axis{spec->name, s.options.from.value_or(spec->min), s.options.to.value_or(spec->max), spec->min, spec->max};
    const std::string range = "[" + format_number(spec->min) + ", " + format_number(spec->max) + "]";
    for (const auto& [option, value] : {std::pair{"--from", axis.from}, std::pair{"--to", axis.to}})
        if (value < spec->min || value > spec->max)
            throw Error(std::string("option ") + option + " = " + format_number(value) + " is out of range " + range +
                        " of parameter '" + spec->name + "'");
    if (axis.from == axis.to)
        throw Error("options --from and --to are both " + format_number(axis.from) + ": nothing to animate");
    return axis;
}

}  // namespace

void check_animate_command(const Session& s) { animation_axis(s); }

int run_animate(Session& s) {
    const Axis axis = animation_axis(s);
    const std::filesystem::path dir = s.options.out_dir.empty() ? "animate-" + s.info.id : s.options.out_dir;
    prepare_output_folder(dir, "--out-dir");
    s.open(s.headless_backend());
    const int width = s.options.width, height = s.options.height, count = s.options.count;
    Framebuffer target = frame_target(s, width, height);
    const Frame frame{width, height, 0.0};

    std::vector<Image> frames;
    int first_bad = -1;
    long nan_values = 0, inf_values = 0;
    for (int i = 0; i < count; ++i) {
        // i / count, not i / (count - 1): the last frame stops one step short of `to`, so a periodic
        // parameter (time, phase) loops without showing the same picture twice.
        const double value = axis.from + (axis.to - axis.from) * i / count;
        // Every bit, so frame i's value is exactly from + step * i; clamped, a rounding ulp is no error.
        s.params.set(axis.name, format_number(std::clamp(value, axis.min, axis.max), 17));
        if (auto error = s.sync_params()) throw Error(*error);
        target.bind();
        s.render_frame(frame);
        check_gl_error(("rendering animation frame " + std::to_string(i)).c_str());
        Readback shot = read_back(target);
        if (shot.non_finite() && first_bad < 0) first_bad = i;
        nan_values += shot.stats.nan_count;
        inf_values += shot.stats.inf_count;
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", i);
        // Each frame's own legend: a range that follows the data (lab 07's auto_range) changes with the frame.
        if (s.options.legend) shot.image = with_lab_legend(s, shot.image);
        write_png(dir / name, shot.image);
        frames.push_back(std::move(shot.image));
    }
    const std::filesystem::path apng = dir / "animation.png";
    write_apng(apng, frames, apng_delay(s.options.fps));

    std::printf("%s: wrote %d frames (%dx%d, %s from %s to %s) as %s ... frame_%04d.png\n", s.info.id.c_str(), count,
                width, height, axis.name.c_str(), format_number(axis.from).c_str(), format_number(axis.to).c_str(),
                (dir / "frame_0000.png").string().c_str(), count - 1);
    std::printf("%s: wrote %s (APNG, %s fps, loops)\n", s.info.id.c_str(), apng.string().c_str(),
                format_number(s.options.fps).c_str());
    if (first_bad >= 0) {
        std::fprintf(stderr, "%s: frames have %ld NaN and %ld Inf pixel values, first in frame_%04d.png (painted magenta)\n",
                     s.info.id.c_str(), nan_values, inf_values, first_bad);
        return kExitNonFinite;
    }
    return kExitOk;
}

}  // namespace gsv
