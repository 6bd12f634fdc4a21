#pragma once
// Grades the labs of one submission headless. Each case is rendered by the student's binary in a sandboxed process
// (one per lab, serving its cases one after another, or one per case: LabProcesses) and compared with the reference: rendered live by <lab>_solution in the same run
// (instructor grading: public and hidden cases, timing) or the committed golden image (self-check). A lab
// that hands in arrays (lab 05's particles) has them checked as well (grader/src/judge/data_check.h).
// The run's set-up is session.h's, each check judge/'s; rewriting the goldens is apart (update/golden_update.h).
#include "grader/src/core/grade_result.h"
#include "grader/src/run/lab_run.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gsv {

// Live references already rendered, by lab, size and settings: a run that grades many submissions (or many
// mutants) in one process renders each reference case once.
struct ReferenceCache {
    std::map<std::string, LabRun> runs;
};

// How the labs' processes are started: one per lab for the student and one for the reference, each rendering the lab's
// cases one after another (render --serve, grader/src/run/lab_serve.h), or one per case.
enum class LabProcesses {
    Default,  // one per lab; one per case for a rerun of named cases (`cases`), which is today's path, a few processes
    PerLab,
    PerCase,  // --one-process-per-case
};

enum class DiagnoseCases { Default, Off, Public, All };

// Where the known mistakes' pictures come from: shipped (grader/golden/<lab>/mistakes.*, what a student's copy has)
// or rendered on this machine from the instructor's lists. Default: shipped where the failures were judged against the
// goldens (a self-check; a student's and the instructor's say the same) and the lab has them, else rendered.
enum class MistakePictureSource { Default, Shipped, Rendered };
// What a passed image case keeps in --out: its picture and the expected one as PNGs, or a JPEG thumbnail of its
// picture only (it matched; a class's folders stay small: grader/README.md, "What a class leaves on disk").
enum class PassedPictures { Full, Thumbnail };

struct GradeOptions {
    std::filesystem::path kit_root;     // grader/cases, golden, hidden; solutions/
    std::filesystem::path bin_dir;      // the kit's build: <lab>_solution, and <lab> when no submission is given
    std::filesystem::path submission;   // empty: grade the kit's own labs/ (as built in bin_dir)
    std::filesystem::path out_dir;      // images and reports
    // Labs built elsewhere, graded as the student's (the tests grade mutants of the solution this way):
    // <lab> in student_bin_dir, run with GSV_ROOT=student_root. Empty: the kit's own build; unused with
    // a submission.
    std::filesystem::path student_bin_dir, student_root;
    std::vector<std::string> labs;      // empty: every lab with a case file
    std::vector<std::string> cases;     // empty: every case; else only these names (an unknown one is an error)
    bool self_check = false;            // golden images only, public cases only, even when solutions are built
    bool timing = true;                 // instructor mode: time the cases that declare a timing band
    bool hidden = true;                 // instructor mode: add the hidden cases drawn from the seed
    bool sandbox = true;                // off only to debug the grader itself
    bool reuse_builds = true;           // false (--build-all): compile every lab of a submission (grader/submission.h)
    std::filesystem::path build_cache;  // earlier builds; empty: <bin_dir>/../grader-cache/builds
    // Where the allow-list walls cannot go up (no namespaces), hidden cases and live references are refused: student
    // code could read the kit. This grades them anyway, and the report says the kit was readable.
    bool allow_readable_kit = false;
    bool namespaces = true;             // false: every wall but the namespaces, as where unshare is refused
    // A root grader runs student code as this uid; 0: the first one free (grader/src/run/uid_lease.h).
    unsigned sandbox_uid = 0;
    std::string todo;                   // only the cases of this TODO ("L02-T3"); empty: all
    std::shared_ptr<ReferenceCache> reference_cache;  // shared between runs in one process; none: no cache
    // Live references kept on disk across runs (grader/src/run/reference_store.h); empty: <bin_dir>/../grader-cache/
    // references. Used only where the allow-list walls are up.
    std::filesystem::path reference_store;
    bool stored_references = true;      // false (--fresh-references): render every live reference (and store it anew)
    std::optional<std::uint64_t> seed;  // hidden cases; none: a fresh seed, recorded in the report
    double timeout_s = 0;               // per student process; 0: the case file's timeout_s (always the reference's)
    // The profile both the student's lab and the reference run on. On ES each lab runs at its lowest ES version
    // (a case's "es" lifts it); the self-check compares with the goldens, which are core-profile images.
    Profile profile = Profile::Core;
    // On ES: every case at least at this version (a case's own "es" above it stands); none: each lab's lowest.
    std::optional<GlVersion> es_at_least;
    // The grades are the same either way (tests/test_grader_serve.cpp); one process per lab is a fraction of the time.
    // A student's lab is served only behind the allow-list walls, whose sandbox can stop it between its cases.
    LabProcesses lab_processes = LabProcesses::Default;
    // Which failing cases are compared with the kit's known mistakes (grader/src/diagnose/diagnosis.h) so the report can
    // name the mistake: none (exams), the public ones (what a student may be told) or all (the instructor's own
    // reports). Default: public in a self-check, all in instructor grading.
    DiagnoseCases diagnose = DiagnoseCases::Default;
    MistakePictureSource mistake_pictures = MistakePictureSource::Default;
    PassedPictures passed_pictures = PassedPictures::Full;
    // A submission's build (<out>/submission-build/build: its binaries, tens of MB) kept after grading; false removes
    // it (its sources, submission-build/kit, stay). A batch's runs and the Gradescope zip do not keep it.
    bool keep_build = true;
};

// What a row's detail gains where a check failed on a render made after other cases in the same process and passed on
// the case rendered again alone (one process per case, what the `reproduce:` line runs): the student's lab keeps
// something from one case to the next.
inline constexpr const char* kPassedOnlyAlone =
    "; rendered again alone, as a process of its own, where it passes: after other cases in the same process it came out "
    "differently, so the lab keeps something between cases (a `static`, a global, a file it wrote); step through the cases "
    "in the window (C) to see it";

struct GradeProgress {
    int done = 0, total = 0;
    const CaseResult* result = nullptr;  // the check just finished; null while building
    std::string stage;                   // "building lab01", ...
};

// Throws gsv::Error on what stops grading as a whole: an unreadable case file, a lab that has none, a
// submission without labs/. Everything a student's code does is a CaseResult.
GradeReport grade(const GradeOptions& options, const std::function<void(const GradeProgress&)>& progress = {});

}  // namespace gsv
