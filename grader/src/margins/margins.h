#pragma once
// The margin table (scripts/kit margins, gsv-margins): how far each grading case's correct renders are from its
// golden, and how far the wrong ones are, measured on every implementation there is. A case holds across GPUs when
// every correct render (the reference solution and the correct variants of tests/mutants/, on every implementation)
// uses under half of the case's golden pixel budget, and every mutant that must fail it is over one and a half
// budgets away, on every implementation. The budget is the case's own: floor(max_differing_fraction x pixels) pixels
// over max_channel_diff (matched within its neighbourhood), and for a lab that hands in arrays the same share of
// each array's compared elements; a render's distance is the largest of those shares.
#include "common/gl/gl_version.h"
#include "common/io/json.h"
#include "grader/src/cases/cases.h"
#include "grader/src/core/grade_result.h"

#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gsv {

// One way of rendering: the machine's own GL, or another rasterizer chosen through the environment (which the grader
// passes on to every lab process).
struct Implementation {
    std::string name;   // "llvmpipe", "softpipe-es", ...
    std::string how;    // "GALLIUM_DRIVER=softpipe, --profile es"
    std::vector<std::pair<std::string, std::string>> environment;
    Profile profile = Profile::Core;
    // Words the renderer string (GL_RENDERER) must hold for the implementation to be what it says; empty: any.
    std::vector<std::string> renderer_holds;
};

// The machine's default GL ("default": llvmpipe here, the GPU's driver on a machine with one), softpipe on ES, two
// llvmpipe variants and the 8-bit filter-weight stand-in (GSV_TEXEL_SNAP=256, shaders/gsv/texel_snap.glsl).
std::vector<Implementation> known_implementations();

// The share of a render that could not be compared, or that differs where the budget is 0: beyond every bar.
inline constexpr double kInfiniteShare = std::numeric_limits<double>::infinity();

inline constexpr double kCorrectBar = 0.5;  // a correct render uses under half the budget...
// ...and a must-fail mutant is over one and a half budgets away: beyond the bar where a failing self-check is called
// a difference between GPUs (cross_implementation_tolerance, grader/cases.h).
inline constexpr double kWrongBar = kCrossImplementationBudget;

// A render's distance from the golden as a share of the case's budget (1 = exactly the budget), or of the whole picture's
// offset the grader refuses (kMaxGlobalOffset, common/image/image_offset.h), whichever is larger; infinity when it
// could not be compared (a crash, a compile error, a missing array) or the budget is 0 and something differs.
double budget_share(const CaseResult& result);

// One graded render of one case.
struct MarginRender {
    std::string implementation, lab, case_name;
    std::string kind;    // "solution", "variant" or "mutant"
    std::string source;  // the variant's or mutant's name; "" for the solution
    double share = 0;    // budget_share
    std::string status, detail;
    double offset = 0;   // the whole picture's offset against the golden, pixels (the larger axis; image_offset.h)
};

struct MarginCase {
    std::string lab, name, todo;
    std::string budget;  // "max channel diff 24, 327 of 32768 px (1%), matched within 1 px"
};

struct MarginImplementationRun {
    Implementation implementation;
    std::string renderer;  // GL_RENDERER as the probe render reported it
    bool available = false;
    std::string why_not;   // when not available
    double seconds = 0;
};

// What the self-check's diagnosis (from the pictures the kit ships, grader/src/diagnose/shipped_diagnosis.h) named
// first for a mutant graded on an implementation: whether it is the mutant (or a twin named with it).
struct MarginDiagnosis {
    std::string implementation, lab, mutant;
    std::string named;  // the first mistake's names as the lists have them, "; "-separated; "" where none was named
    bool right = false;
};

struct MarginMeasurement {
    std::vector<MarginImplementationRun> implementations;
    std::vector<MarginCase> cases;
    std::vector<MarginRender> renders;
    std::vector<MarginDiagnosis> diagnoses;
    std::size_t labs_with_mutants = 0;  // in the kit measured: the diagnosis bar holds where all were measured
    std::vector<std::string> notes;  // what was left out, and why
};

struct MarginOptions {
    std::filesystem::path kit_root, bin_dir, work_dir;
    std::vector<std::string> labs;             // empty: every lab with a case file
    std::vector<std::string> implementations;  // empty: every known one
    bool mutants = true;                       // the mutants too, not only the solutions
    bool variants = true;                      // the correct variants too
    std::optional<GlVersion> es_at_least;      // on ES, every case at least at this version (--es-version)
    // Each mutant graded on its must-fail cases one at a time, up to the first it fails (--check: one failing case is
    // what it is held to); false: on all of them, for the table's nearest mutant.
    bool mutant_until_first_failure = false;
};

// Renders and grades everything (the solutions in self-check, against the goldens; each mutant on the public cases it
// must fail; each correct variant on its TODO's cases), implementation by implementation. `progress` gets a line now
// and then. Throws gsv::Error on an unknown implementation or lab, or a broken case or mutant file.
MarginMeasurement measure_margins(const MarginOptions& options, const std::function<void(const std::string&)>& progress = {});

// The measurement as JSON and back, so runs on several machines (or implementations run apart) make one table.
Json margins_json(const MarginMeasurement& m);
MarginMeasurement margins_from_json(const Json& j);
// Several measurements as one: implementations, cases (once each) and renders joined.
MarginMeasurement merge_margins(const std::vector<MarginMeasurement>& parts);

// The table: per case the worst correct render and the nearest must-fail mutant, as shares of the budget, where each
// was measured, and whether the case meets the bar (and if not, why); then the cases that miss it.
std::string margins_table(const MarginMeasurement& m);
// The cases that miss the bar, one line each saying why; empty when every case meets it.
std::vector<std::string> cases_missing_the_bar(const MarginMeasurement& m);

// The least share of mutants whose first diagnosis must be right on an implementation (the bar: the same
// first name across implementations for nine in ten).
inline constexpr double kDiagnosisBar = 0.9;

// What CI holds an implementation to (the softpipe kind of test): every correct render passes (the solutions at full
// marks), every mutant loses points on a case it must fail, the diagnosis gives no mutant another mistake's name, and
// (measuring every lab) names the mutant first for at least kDiagnosisBar of those that failed on a picture. One line per failure, naming the implementation and
// its GL_RENDERER; empty when all hold.
std::vector<std::string> grading_failures(const MarginMeasurement& m);

}  // namespace gsv
