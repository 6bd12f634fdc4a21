// Sweep mode: what accuracy costs in time. Steps the lab's accuracy knob; measures each setting's error against the
// reference its sweep plan names (exact where a yardstick draws one, else a rendered one, named and checked for
// convergence); then times
// every setting interleaved with the others; prints a table and writes a CSV, a Markdown table and plots.
#include "common/app/app_session.h"
#include "common/app/sweep_plan.h"
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

namespace {

// What is swept: the knob's values, on each curve of the lab's series (or one curve), written where --out-dir says.
struct SweepScope {
    SweepAxis axis;
    std::string series_name;                  // empty: one curve
    std::vector<std::string> series_values{""};
    std::filesystem::path dir;
};

SweepScope scope_sweep(Session& s) {
    SweepScope scope;
    scope.axis = sweep_axis(s);
    s.params.check_applies({scope.axis.name}, "sweep: the swept parameter ");
    scope.dir = s.options.out_dir.empty() ? "sweep-" + s.info.id : s.options.out_dir;
    prepare_output_folder(scope.dir, "--out-dir");
    if (const ParamSpec* series = s.params.series()) {
        scope.series_name = series->name;
        scope.series_values = series->choices;
        // `--set integrator=rk4` asks for one curve, not all of them.
        for (const auto& assignment : s.options.assignments)
            if (assignment.rfind(scope.series_name + "=", 0) == 0) scope.series_values = {s.params.get_text(scope.series_name)};
    }
    return scope;
}

std::string point_name(const std::vector<std::string>& settings) {
    std::string name;
    for (const auto& setting : settings) name += (name.empty() ? "" : " ") + setting;
    return name;
}

// One sweep, in the order it runs: each point's error against the reference first, then the reference named (and its
// convergence shown where the lab says how to refine it), then every point timed, interleaved with the others.
class SweepRun {
public:
    SweepRun(Session& s, const SweepScope& scope, SweepPlan& lab_plan)
        : s_(s), scope_(scope), lab_plan_(lab_plan), knob_name_(scope.axis.name), knob_values_(scope.axis.values), series_name_(scope.series_name),
          series_values_(scope.series_values) {
        s.open(s.headless_backend());
        target_ = Framebuffer(s.options.width, s.options.height, ColorFormat::RGBA8);
        frame_ = Frame{s.options.width, s.options.height, 0.0};
        warmup_ = s.options.warmup >= 0 ? s.options.warmup : 2;
        const int frames = s.options.frames > 0 ? s.options.frames : 9;
        // Frames are timed in rounds over every point (A B C ... A B C ...): three rounds where the frames allow.
        rounds_ = std::min(3, frames);
        frames_per_round_ = std::max(1, frames / rounds_);
        base_ = s.params;

        // The lab's reference belongs to its own knob; another knob converges at its last value.
        if (scope.axis.lab_knob) reference_settings_ = lab_plan.reference();
        if (reference_settings_.empty()) reference_settings_.push_back(knob_name_ + "=" + knob_values_.back());
        // One reference, or one per series value, drawn when first needed: not at all where the lab draws exact ones.
        per_series_ = lab_plan.reference_per_series() && !series_name_.empty();
        references_.resize(per_series_ ? series_values_.size() : 1);

        report_.lab = s.info.id;
        report_.knob = knob_name_;
        report_.series = series_name_;
        report_.reference = reference_settings_;
        if (per_series_) report_.reference.push_back(series_name_ + "=<each curve's>");
        report_.gl = s.context->describe();
        report_.width = s.options.width;
        report_.height = s.options.height;
        report_.plotted_error = lab_plan.error_column();
        // This device's ceilings, where gsv-ceilings has measured them (never measured here: a sweep times the lab).
        ceilings_ = cached_ceilings(s.executable, s.context->info().renderer);

        // Each point is a step of the progress line, and so is each switch to it while timing (once to size its
        // batches, then once a round).
        planned_points_ = static_cast<int>(series_values_.size() * knob_values_.size());
        progress_.emplace("sweep " + s.info.id, planned_points_ * (2 + rounds_));
    }

    void measure_errors() {
        for (std::size_t curve = 0; curve < series_values_.size(); ++curve)
            for (const auto& knob_value : knob_values_) measure_error(curve, knob_value);
        // Nothing left to time or plot (lab 05's particles past this GPU's storage blocks, at every local size): the
        // sweep is refused with the first point's reason, and a script running sweeps can tell it from a failure.
        if (report_.rows.empty() && left_out_ > 0)
            throw UnsupportedError("every setting of the sweep was left out; the first: " + first_left_out_);
    }

    // The reference in words, and whether it is shown to be converged.
    void name_reference() {
        const std::string named = scope_.axis.lab_knob ? lab_plan_.reference_name() : std::string();
        const std::string joined = point_name(reference_settings_);
        if (exact_) {
            report_.reference_name = named.empty() ? "an exact image the sweep plan draws" : named;
            return;
        }
        const bool lab_reference = scope_.axis.lab_knob && !lab_plan_.reference().empty();
        report_.reference_name = !named.empty()   ? named + " (" + joined + ")"
                                 : lab_reference ? joined
                                 : s_.make_sweep_plan ? joined + " (the last value swept; not shown converged)"
                                                      : joined + " (the last value swept; not shown converged: this build has no "
                                                                 "sweep plan, the instructor's reference/)";
        const std::vector<std::string> refinement =
            scope_.axis.lab_knob ? lab_plan_.refinement() : std::vector<std::string>{};
        if (!refinement.empty()) show_convergence(refinement);
    }

    void time_points() {
        std::vector<TimedWork> work;
        for (const auto& settings : point_settings_)
            work.push_back({[this, settings] {
                                use(settings);
                                progress_->step("timing " + point_name(settings));
                            },
                            [this] { draw(); }});
        const std::vector<TimingStats> times = time_interleaved(work, warmup_, frames_per_round_, rounds_).stats;
        progress_->finish();
        for (std::size_t i = 0; i < report_.rows.size(); ++i) {
            SweepRow& row = report_.rows[i];
            row.median_ms = times[i].median_ms;
            row.min_ms = times[i].min_ms;
            row.p25_ms = times[i].p25_ms;
            row.p75_ms = times[i].p75_ms;
            if (ceilings_) row.roofline = roofline(point_work_[i], *ceilings_);
            if (row.roofline && !row.roofline->upper_bound && row.median_ms < row.roofline->bound_ms)
                std::fprintf(stderr, "  %s=%s: %.3f ms is faster than this device's %s ceiling allows (%.3f ms at its "
                                     "fastest): a frame that was not waited for, or work overstated\n",
                             knob_name_.c_str(), row.knob.c_str(), row.median_ms, row.roofline->limiter.c_str(),
                             row.roofline->bound_ms);
            std::fprintf(stderr, "  %s%s%s %s=%s: %.3f ms [%.3f, %.3f], rmse %.3f\n", series_name_.c_str(),
                         series_name_.empty() ? "" : "=", row.series.c_str(), knob_name_.c_str(), row.knob.c_str(),
                         row.median_ms, row.p25_ms, row.p75_ms, row.rmse);
        }
        s_.params = base_;
    }

    int write() {
        std::printf("%s", report_.table().c_str());
        const auto files = report_.write(scope_.dir);
        for (const auto& f : files) std::printf("wrote %s\n", f.c_str());
        return kExitOk;
    }

private:
    void use(const std::vector<std::string>& settings) {
        s_.params = base_;
        for (const auto& setting : settings) s_.params.set_assignment(setting);
        if (auto error = s_.sync_params()) throw Error(*error);
    }
    void draw() {
        target_.bind();
        s_.render_frame(frame_);
    }
    Image image_with(const std::vector<std::string>& settings) {
        use(settings);
        time_frames([this] { draw(); }, 1, 1);
        check_gl_error("rendering a sweep point");
        return target_.read_rgba8();
    }
    const Image& reference_of(std::size_t curve) {
        std::optional<Image>& reference = references_[per_series_ ? curve : 0];
        if (!reference) {
            std::vector<std::string> settings = reference_settings_;
            if (per_series_) settings.push_back(series_name_ + "=" + series_values_[curve]);
            reference = image_with(settings);
        }
        return *reference;
    }

    // What one point draws, and how far it is from the reference (an exact image of the plan's, or the curve's).
    void measure_error(std::size_t curve, const std::string& knob_value) {
        const std::string& series_value = series_values_[curve];
        std::vector<std::string> settings{knob_name_ + "=" + knob_value};
        if (!series_name_.empty()) settings.push_back(series_name_ + "=" + series_value);
        Image image;
        try {
            image = image_with(settings);
        } catch (const UnsupportedError& e) {
            // A point this GPU cannot draw (lab 03's separate textures past the unit limit) is left out, said once,
            // and the rest of the sweep goes on.
            progress_->finish();
            std::fprintf(stderr, "  %s=%s %s=%s: left out: %s\n", series_name_.c_str(), series_value.c_str(),
                         knob_name_.c_str(), knob_value.c_str(), e.what());
            if (left_out_ == 0) first_left_out_ = e.what();
            ++left_out_;  // a step now, and none while timing
            progress_->set_total(planned_points_ * (2 + rounds_) - left_out_ * (1 + rounds_));
            progress_->step("left out " + point_name(settings));
            return;
        }
        const std::optional<Image> exact_image =
            scope_.axis.lab_knob ? lab_plan_.exact_image(*s_.kit, frame_) : std::nullopt;
        exact_ = exact_ || exact_image.has_value();
        SweepRow row;
        row.series = series_value;
        row.knob = knob_value;
        row.extra = lab_plan_.metrics(*s_.kit, frame_);  // while this point's settings are current
        const FrameWork work = s_.lab->frame_work(frame_);
        row.work = work.summary();
        point_work_.push_back(work);
        const ImageDiff diff = compare_images(image, exact_image ? *exact_image : reference_of(curve), ImageTolerance{});
        row.rmse = diff.rmse;
        row.max_diff = diff.max_channel_diff;
        report_.rows.push_back(row);
        point_settings_.push_back(settings);
        progress_->step("error of " + point_name(settings));
    }

    // Each reference against its own refinement; the worst of them is reported, beside the smallest error measured
    // against it.
    void show_convergence(const std::vector<std::string>& refinement) {
        const std::string next = point_name(refinement);
        bool converged = true;
        double worst_change = 0, smallest_beside = 0;
        for (std::size_t i = 0; i < references_.size(); ++i) {
            std::vector<std::string> settings = refinement;
            if (per_series_) settings.push_back(series_name_ + "=" + series_values_[i]);
            const Image& reference = reference_of(i);
            const double change = compare_images(image_with(settings), reference, ImageTolerance{}).rmse;
            double smallest = -1;
            for (const auto& r : report_.rows)
                if ((!per_series_ || r.series == series_values_[i]) && r.rmse > 0 && (smallest < 0 || r.rmse < smallest))
                    smallest = r.rmse;
            if (i == 0 || change > worst_change) worst_change = change, smallest_beside = smallest;
            if (smallest >= 0 && change >= smallest) converged = false;
        }
        report_.reference_name += std::string(converged ? "; converged: " : "; NOT shown converged: ") + "its refinement " +
                                  next + " changes it by RMSE " + format_number(worst_change, 3);
        if (smallest_beside >= 0)
            report_.reference_name += std::string(converged ? ", below" : ", not below") +
                                      " the smallest error measured against it, " + format_number(smallest_beside, 3);
    }

    Session& s_;
    const SweepScope& scope_;
    SweepPlan& lab_plan_;
    const std::string knob_name_;
    const std::vector<std::string> knob_values_;
    const std::string series_name_;
    const std::vector<std::string> series_values_;
    Framebuffer target_;
    Frame frame_{};
    int warmup_ = 0, rounds_ = 0, frames_per_round_ = 0;
    Params base_;
    std::vector<std::string> reference_settings_;
    bool per_series_ = false;
    std::vector<std::optional<Image>> references_;
    SweepReport report_;
    int planned_points_ = 0;
    std::optional<Progress> progress_;
    std::vector<std::vector<std::string>> point_settings_;
    std::vector<FrameWork> point_work_;
    std::optional<Ceilings> ceilings_;
    int left_out_ = 0;
    std::string first_left_out_;
    bool exact_ = false;
};

}  // namespace

int run_sweep(Session& s) {
    const SweepScope scope = scope_sweep(s);
    // The lab's plan where its solution build links one (reference/<lab dir>/sweep_plan.cpp); else the default.
    const std::unique_ptr<SweepPlan> lab_plan =
        s.make_sweep_plan ? s.make_sweep_plan(*s.lab) : std::make_unique<SweepPlan>();
    SweepRun run(s, scope, *lab_plan);
    run.measure_errors();
    run.name_reference();
    run.time_points();
    return run.write();
}

}  // namespace gsv
