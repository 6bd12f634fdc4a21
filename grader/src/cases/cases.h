#pragma once
// A lab's grading cases, declared as data: the public ones in grader/cases/<lab>.json (shipped to
// students, with golden images), the hidden ones in grader/hidden/<lab>.json (instructors only), whose
// parameters are drawn from the seed given at grading time.
#include "common/gl/gl_features.h"
#include "common/gl/gl_version.h"
#include "common/image/image_compare.h"
#include "common/io/json.h"
#include "grader/src/core/array_diff.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gsv {

struct TimingSpec {
    double points = 0;      // 0: not timed
    double max_ratio = 2;   // student median frame time over the reference's
    // "vary": what changes from timed frame to timed frame, drawn afresh for each (grader/src/cases/draw.h's language,
    // e.g. {"camera_yaw": {"range": [-30, 30]}}): the grader's challenge, which a frame cannot be drawn without.
    std::optional<Json> vary;
};

struct GradeCase {
    std::string name, todo, description, visibility = "public";
    double points = 1;
    std::vector<std::string> settings;  // name=value, as for --set
    TimingSpec timing;
    // "arrays": which of the arrays the lab hands in this case checks; none given: every array the reference
    // hands in (an empty list: none).
    std::optional<std::vector<std::string>> arrays;
    // "tolerance": {"live": ..., "golden": ...}: this case's own, where the lab's would hide a bug it is there to catch.
    std::optional<ImageTolerance> live_tolerance, golden_tolerance;
    // "needs": the other TODOs this case cannot pass without (its own "todo" aside).
    std::vector<std::string> needs;
    // "es": "3.2": the OpenGL ES version this case needs where it is above the lab's lowest (a setting that uses
    // what ES 3.0 lacks); graded on --profile es at that version.
    std::optional<GlVersion> es_version;
    // "feature": "compute": what the case's TODO runs on (lab 05's dispatch: compute shaders). On OpenGL ES it lifts
    // the case to the feature's first ES version, as "es" does; a run whose context lacks it (macOS's 4.1, WebGL 2)
    // draws the case without the student's code for it, so there the case is not counted, and the report says why.
    const GlFeature* feature = nullptr;
};

struct LabCases {
    std::string lab;
    int width = 256, height = 256;
    ImageTolerance live_tolerance;    // against the reference rendered in the same run, same machine
    ImageTolerance golden_tolerance;  // against committed golden images: another GPU and driver
    // "tolerance": {"arrays": ...}: the lab hands in numbers that are checked too (common/io/data_array.h); none:
    // only images are. Against goldens "arrays_golden" where given, else "arrays".
    std::optional<ArrayTolerance> live_array_tolerance, golden_array_tolerance;
    bool checks_arrays() const { return live_array_tolerance.has_value(); }
    // "arrays_are": what the arrays describe, a plural noun for messages ("particles match the reference; the
    // picture differs ..." where only the image fails).
    std::string arrays_are = "the arrays";
    double timeout_s = 60;
    ImageTolerance tolerance(const GradeCase& c, bool live) const {
        return live ? c.live_tolerance.value_or(live_tolerance) : c.golden_tolerance.value_or(golden_tolerance);
    }
    // Timing: its own size (large enough that the lab's own work, not fixed costs, sets the frame
    // time), frames per process after warm-up, and interleaved student/reference rounds.
    int timing_width = 1024, timing_height = 1024;
    int timing_frames = 5, timing_warmup = 2, timing_rounds = 2;
    std::vector<GradeCase> cases;
};

// The looser bar a failing self-check case is held to before it is called a difference between GPUs rather than a
// wrong image: the case's own golden tolerance with kCrossImplementationBudget times its pixel budget. The margin table
// (grader/margins.h) holds every case to correct renders under half the budget on every implementation measured and
// every must-fail mutant over this many budgets, so a render between one and this many budgets away is one no known
// bug gives. (Matching within a pixel as well would be looser still, but lets known bugs by: on lab 03's LIC, whose
// noise matches itself a pixel off, two slices averaged came to 17% of such a bar.)
inline constexpr double kCrossImplementationBudget = 1.5;
ImageTolerance cross_implementation_tolerance(const ImageTolerance& own);

// Each throws gsv::Error naming the file, the member and what is wrong.
LabCases load_lab_cases(const std::filesystem::path& file);
// Appends the hidden cases of `file`, drawn from `seed`: a case with "count": n becomes n cases
// <name>-1 .. <name>-n, each with its own draw.
void add_hidden_cases(LabCases& lab, const std::filesystem::path& file, std::uint64_t seed);
std::vector<std::filesystem::path> case_files(const std::filesystem::path& kit_root);
std::filesystem::path hidden_case_file(const std::filesystem::path& kit_root, const std::string& lab);

}  // namespace gsv
