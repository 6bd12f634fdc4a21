#pragma once
// What grading found: one result per check (a case's image and the numbers its lab hands in, or its frame
// time against the reference's), the per-lab builds, and how the run was set up. The reports are written from
// this.
#include "common/image/image_compare.h"
#include "grader/src/core/array_diff.h"
#include "grader/src/core/case_status.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace gsv {

struct ImageCheck {
    bool done = false;
    ImageTolerance tolerance;
    int max_channel_diff = 0;
    long differing_pixels = 0, total_pixels = 0;
    double psnr = 0, ssim = 0;
    int diff_x0 = 0, diff_y0 = 0, diff_x1 = -1, diff_y1 = -1;  // inclusive box of differing pixels
    // The whole picture's offset against the reference (common/image/image_offset.h), pixels, x right and y down.
    double offset_x = 0, offset_y = 0;
};

// The arrays a case checks (grader/src/judge/data_check.h); a case passes only if its image and these both pass.
struct DataCheck {
    bool done = false;
    std::string reference;        // "live" or "golden" (a golden holds a sample of each array)
    ArrayTolerance tolerance;
    std::vector<ArrayDiff> arrays;
    std::string describes = "the arrays";  // the lab's "arrays_are": "particles"
    bool passed() const;          // every array within the tolerance (vacuously when none is checked)
};

struct TimingCheck {
    bool done = false;
    double student_ms = 0, reference_ms = 0;  // medians over the interleaved rounds
    double ratio = 0, max_ratio = 0;          // student over reference, and the case's pass band
    int rounds = 0;
    bool remeasured = false;                  // the first measurement was near the band
};

struct CaseResult {
    std::string lab, name, todo, description;
    std::string visibility = "public";        // "public" or "hidden"
    std::string kind = "image";               // "image" or "timing"
    std::vector<std::string> settings;        // name=value, as given to the lab with --set
    double points = 0, max_points = 0;
    CaseStatus status = CaseStatus::Error;
    std::string detail;     // one line for the table
    std::string reproduce;  // the command that draws what the student's lab drew here
    std::string output;     // what helps the student: compiler messages, the lab's own output
    std::string reference;  // "live" (rendered in this run) or "golden" (committed image)
    double seconds = 0;     // wall time of the student's process
    double reference_seconds = 0;  // wall time of the live reference's process
    double frame_ms = 0;           // the student's own frame time inside that process (the rest is start-up)
    ImageCheck image;
    DataCheck data;
    TimingCheck timing;
    // Relative to the output folder; empty when there is none.
    std::string actual_png, expected_png, diff_png;
    // A failure a known mistake of the kit explains (grader/src/diagnose/diagnosis.h): what it says to the student, its
    // TODO (where the failure is put, whatever TODO the case carries), the part of the lab's sheet that teaches it, and
    // its picture of this case (relative to the output folder). Empty where none explains it or none was looked for;
    // only mistake_todo where the TODO is not started (its picture is the starter's, though the starter draws no magenta).
    std::string mistake, mistake_todo, mistake_sheet, mistake_png;
};

// A known mistake that explains some of a lab's failing cases. `names` are the kit's own names of it, for the instructor
// (the mistakes whose pictures are the same on every failing case: twins); the student sees `says`.
struct MistakeFound {
    std::string todo, says, sheet;
    std::vector<std::string> names;
    std::vector<std::string> cases;  // the failing cases it explains, none of them explained by a mistake named before it
    bool with_earlier = false;       // it explains them made together with the mistakes named before it
};

// What the failing cases of one lab come down to: the fewest known mistakes that explain the most of them, in order,
// and those none explains.
struct LabDiagnosis {
    std::string lab;
    std::vector<std::string> failing;      // the failing cases looked at (a wrong picture or wrong numbers)
    std::vector<MistakeFound> found;
    std::vector<std::string> unexplained;  // failing cases no known mistake explains
    std::vector<std::string> not_started;  // TODOs whose cases show the starter's not-done colour
    std::string compare;                   // the command that compares an unexplained public case with the reference
    // Where a student starts (grader/src/judge/needs.h, way_in): a TODO with a case that needs no other TODO.
    std::string way_in;
};

struct LabBuild {
    std::string lab;
    bool ok = false;
    std::string log;  // compiler output, capped
    double seconds = 0;
    // How the binary came to be: "built", or, where the lab's C++ is byte for byte one already built, "unchanged C++:
    // the kit's binary" or "unchanged C++: an earlier build" (grader/submission.h says when).
    std::string origin = "built";
    // The build failed for the kit's reason: the submission project does not configure even without the student's
    // files. Its checks are KitFault, not BuildError.
    bool kit_fault = false;
};

struct GradeReport {
    std::string submission;   // what was graded: a folder, or the kit's own labs/
    std::string mode;         // "instructor" (live reference, hidden cases, timing) or "self-check"
    std::string profile = "core";  // the GL profile the labs ran on: core, compat or es
    std::string renderer;     // GL_RENDERER the student's labs ran on, as they reported it; empty when none did
    // Against goldens: GL_RENDERER each graded lab's goldens were rendered on (grader/golden/renderer.json), by lab.
    std::map<std::string, std::string> golden_renderers;
    std::uint64_t seed = 0;   // hidden cases were drawn from it
    bool hidden_included = false, timing_included = false;
    std::string sandbox;      // which isolation the platform allowed, in words
    std::string references;   // live references: how many rendered, how many from the store; empty without any
    double seconds = 0;       // wall time of the whole run
    std::vector<LabBuild> builds;
    std::vector<CaseResult> results;
    // --regrade-only changed (grader/src/grade/regrade.h): the labs graded in this run, and those whose rows were kept
    // from the last run in the same --out because nothing they depend on changed. Both empty in a plain run.
    std::vector<std::string> regraded, kept;
    // --diagnose: which failing cases were compared with the known mistakes' pictures ("off", "public" or "all"), and
    // what was found, by lab (only labs with a failing case looked at); `diagnosis_note` says why none could be looked
    // at where the run could not (no known mistakes in this kit, no solutions built, walls down).
    std::string diagnose = "off";
    std::vector<LabDiagnosis> diagnoses;
    std::string diagnosis_note;

    double score() const;
    double max_score() const;
};

}  // namespace gsv
