// Sweep mode: what accuracy costs in time. Steps the lab's accuracy knob; measures each setting's error against the
// lab's reference (exact where the lab draws one, else a rendered one, named and checked for convergence); then times
// every setting interleaved with the others; prints a table and writes a CSV, a Markdown table and plots.
#include "common/app/app_session.h"
#include "common/app/sweep_report.h"
#include "common/core/number_text.h"
#include "common/core/progress.h"
#include "common/core/error.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/image/image.h"
#include "common/image/image_compare.h"
#include "common/io/output_folder.h"
#include "common/timing/timing.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>

namespace gsv {
namespace {

// The swept parameter and its values: the lab's accuracy knob, or --knob NAME --values A,B,C.
struct SweepAxis {
    std::string name;
    std::vector<std::string> values;
    bool lab_knob = true;
};

SweepAxis sweep_axis(const Session& s) {
    if (s.options.knob.empty()) {
        if (!s.options.values.empty()) throw Error("--values needs --knob NAME: the parameter they are values of");
        const ParamSpec* knob = s.params.knob();
        if (!knob) throw Error(s.info.id + " declares no accuracy knob to sweep");
        return {knob->name, knob->sweep_values, true};
    }
    const ParamSpec& spec = s.params.spec(s.options.knob);  // names the lab's parameters if unknown
    if (s.options.values.size() < 2)
        throw Error("--knob " + spec.name + " needs --values with at least two values, least accurate first");
    Params check = s.params;
    for (const auto& value : s.options.values) check.set(spec.name, value);  // refuses an out-of-range value by name
    // The lab's own knob through other values keeps the lab's reference.
    const ParamSpec* knob = s.params.knob();
    return {spec.name, s.options.values, knob && knob->name == spec.name};
}

}  // namespace

void check_sweep_command(const Session& s) { sweep_axis(s); }

int run_sweep(Session& s) {
    const SweepAxis axis = sweep_axis(s);
    s.params.check_applies({axis.name}, "sweep: the swept parameter ");
    const std::filesystem::path dir = s.options.out_dir.empty() ? "sweep-" + s.info.id : s.options.out_dir;
    prepare_output_folder(dir, "--out-dir");
    const std::string knob_name = axis.name;
    const std::vector<std::string> knob_values = axis.values;
    std::vector<std::string> series_values{""};
    std::string series_name;
    if (const ParamSpec* series = s.params.series()) {
        series_name = series->name;
        series_values = series->choices;
        // `--set integrator=rk4` asks for one curve, not all of them.
        for (const auto& assignment : s.options.assignments)
            if (assignment.rfind(series_name + "=", 0) == 0) series_values = {s.params.get_text(series_name)};
    }

    s.open(s.options.backend.value_or(Backend::Egl));
    const int width = s.options.width, height = s.options.height;
    Framebuffer target(width, height, ColorFormat::RGBA8);
    const Frame frame{width, height, 0.0};
    const int warmup = s.options.warmup >= 0 ? s.options.warmup : 2;
    const int frames = s.options.frames > 0 ? s.options.frames : 9;
    // Frames are timed in rounds over every point (A B C ... A B C ...): three rounds where the frames allow.
    const int rounds = std::min(3, frames);
    const int frames_per_round = std::max(1, frames / rounds);
    const Params base = s.params;

    auto use = [&](const std::vector<std::string>& settings) {
        s.params = base;
        for (const auto& setting : settings) s.params.set_assignment(setting);
        if (auto error = s.sync_params()) throw Error(*error);
    };
    auto draw = [&] {
        target.bind();
        s.render_frame(frame);
    };
    auto image_with = [&](const std::vector<std::string>& settings) {
        use(settings);
        time_frames(draw, 1, 1);
        check_gl_error("rendering a sweep point");
        return target.read_rgba8();
    };

    // The lab's reference belongs to its own knob; another knob converges at its last value.
    std::vector<std::string> reference_settings = axis.lab_knob ? s.lab->sweep_reference() : std::vector<std::string>{};
    if (reference_settings.empty()) reference_settings.push_back(knob_name + "=" + knob_values.back());
    // One reference, or one per series value, drawn when first needed: not at all where the lab draws exact ones.
    const bool per_series = s.lab->sweep_reference_per_series() && !series_name.empty();
    std::vector<std::optional<Image>> references(per_series ? series_values.size() : 1);
    auto reference_of = [&](std::size_t curve) -> const Image& {
        std::optional<Image>& reference = references[per_series ? curve : 0];
        if (!reference) {
            std::vector<std::string> settings = reference_settings;
            if (per_series) settings.push_back(series_name + "=" + series_values[curve]);
            reference = image_with(settings);
        }
        return *reference;
    };

    SweepReport report;
    report.lab = s.info.id;
    report.knob = knob_name;
    report.series = series_name;
    report.reference = reference_settings;
    if (per_series) report.reference.push_back(series_name + "=<each curve's>");
    report.gl = s.context->describe();
    report.width = width;
    report.height = height;
    report.plotted_error = s.lab->sweep_error_column();

    // First what each point draws and how far it is from the reference; the times after, interleaved. Each
    // point is a step of the progress line, and so is each switch to it while timing (once to size its
    // batches, then once a round).
    const int planned_points = static_cast<int>(series_values.size() * knob_values.size());
    Progress progress("sweep " + s.info.id, planned_points * (2 + rounds));
    auto point_name = [&](const std::vector<std::string>& settings) {
        std::string name;
        for (const auto& setting : settings) name += (name.empty() ? "" : " ") + setting;
        return name;
    };
    std::vector<std::vector<std::string>> point_settings;
    int left_out = 0;
    bool exact = false;
    for (std::size_t curve = 0; curve < series_values.size(); ++curve) {
        const std::string& series_value = series_values[curve];
        for (const auto& knob_value : knob_values) {
            std::vector<std::string> settings{knob_name + "=" + knob_value};
            if (!series_name.empty()) settings.push_back(series_name + "=" + series_value);
            Image image;
            try {
                image = image_with(settings);
            } catch (const UnsupportedError& e) {
                // A point this GPU cannot draw (lab 03's separate textures past the unit limit) is left out,
                // said once, and the rest of the sweep goes on.
                progress.finish();
                std::fprintf(stderr, "  %s=%s %s=%s: left out: %s\n", series_name.c_str(), series_value.c_str(),
                             knob_name.c_str(), knob_value.c_str(), e.what());
                ++left_out;  // a step now, and none while timing
                progress.set_total(planned_points * (2 + rounds) - left_out * (1 + rounds));
                progress.step("left out " + point_name(settings));
                continue;
            }
            const std::optional<Image> exact_image = axis.lab_knob ? s.lab->sweep_exact_image(*s.kit, frame) : std::nullopt;
            exact = exact || exact_image.has_value();
            SweepRow row;
            row.series = series_value;
            row.knob = knob_value;
            row.extra = s.lab->sweep_metrics(*s.kit, frame);  // while this point's settings are current
            const ImageDiff diff = compare_images(image, exact_image ? *exact_image : reference_of(curve), ImageTolerance{});
            row.rmse = diff.rmse;
            row.max_diff = diff.max_channel_diff;
            report.rows.push_back(row);
            point_settings.push_back(settings);
            progress.step("error of " + point_name(settings));
        }
    }

    // The reference in words, and whether it is shown to be converged.
    const std::string named = axis.lab_knob ? s.lab->sweep_reference_name() : std::string();
    std::string joined;
    for (const auto& r : reference_settings) joined += (joined.empty() ? "" : " ") + r;
    if (exact) {
        report.reference_name = named.empty() ? "an exact image the lab draws" : named;
    } else {
        const bool lab_reference = axis.lab_knob && !s.lab->sweep_reference().empty();
        report.reference_name = !named.empty()   ? named + " (" + joined + ")"
                                : lab_reference ? joined
                                                : joined + " (the last value swept; not shown converged)";
        const std::vector<std::string> refinement = axis.lab_knob ? s.lab->sweep_reference_refinement() : std::vector<std::string>{};
        if (!refinement.empty()) {
            // Each reference against its own refinement; the worst of them is reported, beside the smallest
            // error measured against it.
            std::string next;
            for (const auto& r : refinement) next += (next.empty() ? "" : " ") + r;
            bool converged = true;
            double worst_change = 0, smallest_beside = 0;
            for (std::size_t i = 0; i < references.size(); ++i) {
                std::vector<std::string> settings = refinement;
                if (per_series) settings.push_back(series_name + "=" + series_values[i]);
                const Image& reference = reference_of(i);
                const double change = compare_images(image_with(settings), reference, ImageTolerance{}).rmse;
                double smallest = -1;
                for (const auto& r : report.rows)
                    if ((!per_series || r.series == series_values[i]) && r.rmse > 0 && (smallest < 0 || r.rmse < smallest))
                        smallest = r.rmse;
                if (i == 0 || change > worst_change) worst_change = change, smallest_beside = smallest;
                if (smallest >= 0 && change >= smallest) converged = false;
            }
            report.reference_name += std::string(converged ? "; converged: " : "; NOT shown converged: ") + "its refinement " + next +
                                     " changes it by RMSE " + format_number(worst_change, 3);
            if (smallest_beside >= 0)
                report.reference_name += std::string(converged ? ", below" : ", not below") + " the smallest error measured against it, " +
                                         format_number(smallest_beside, 3);
        }
    }

    std::vector<TimedWork> work;
    for (const auto& settings : point_settings)
        work.push_back({[&, settings] {
                            use(settings);
                            progress.step("timing " + point_name(settings));
                        },
                        draw});
    const std::vector<TimingStats> times = time_interleaved(work, warmup, frames_per_round, rounds).stats;
    progress.finish();
    for (std::size_t i = 0; i < report.rows.size(); ++i) {
        SweepRow& row = report.rows[i];
        row.median_ms = times[i].median_ms;
        row.min_ms = times[i].min_ms;
        row.p25_ms = times[i].p25_ms;
        row.p75_ms = times[i].p75_ms;
        std::fprintf(stderr, "  %s%s%s %s=%s: %.3f ms [%.3f, %.3f], rmse %.3f\n", series_name.c_str(), series_name.empty() ? "" : "=",
                     row.series.c_str(), knob_name.c_str(), row.knob.c_str(), row.median_ms, row.p25_ms, row.p75_ms, row.rmse);
    }
    s.params = base;

    std::printf("%s", report.table().c_str());
    const auto files = report.write(dir);
    for (const auto& f : files) std::printf("wrote %s\n", f.c_str());
    return kExitOk;
}

}  // namespace gsv
