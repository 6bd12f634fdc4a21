#pragma once
// Runs a lab binary headless on one case, in a working folder of its own (a process for the case, or one that serves
// the lab's cases one after another: lab_serve.h), and takes only what it hands in over the hand-in socket
// (common/io/handin.h): its image (size-checked), its JSON report and, for a lab whose cases check arrays, the arrays. Nothing is read from the folder the lab wrote into. A timed run also answers the
// grader's challenges: each timed frame drawn with settings drawn afresh, timed from the challenge to the last
// byte of the answer, and kept for checking against the reference's frame with the same settings.
#include "common/gl/gl_version.h"
#include "common/image/image.h"
#include "common/io/data_array.h"
#include "grader/src/cases/cases.h"
#include "grader/src/core/grade_result.h"
#include "grader/src/run/process.h"

#include <filesystem>
#include <optional>
#include <string>

namespace gsv {

struct LabRun {
    ProcessResult process;
    CaseStatus status = CaseStatus::Error;  // Passed: it ran, and image is set
    std::string detail;
    std::optional<Image> image;
    std::vector<DataArray> arrays;  // only for a lab that checks arrays, and not for timed runs
    // A timed run: each challenge's settings, the frame that answered it, and the time from challenge to answer
    // by the grader's clock (ms); median_ms is their median.
    std::vector<std::vector<std::string>> challenges;
    std::vector<Image> frames;
    std::vector<double> frame_ms;
    double median_ms = 0;
    double reported_ms = 0;  // the lab's own claim of its frame time: shown in benchmarks, never graded
    std::string renderer;    // GL_RENDERER as the lab's report gives it (what it ran on, in words): shown, never graded
    // The case's "feature" where the lab's context lacks it (missing_feature_message): the case is not counted.
    std::string lacks;
    // Rendered by a served process that had answered earlier cases (lab_serve.h): what those left (a `static`, a file)
    // could have changed it, so a check that fails on it is rendered again alone (grader/src/grade/grade.cpp).
    bool after_other_cases = false;
};

class ServedLab;

struct LabRunner {
    std::filesystem::path bin_dir;
    std::filesystem::path root;  // GSV_ROOT for the lab (a submission's kit view); empty: the binary's own
    bool student = false;        // its working folder is handed to the sandbox user
    // The GL profile the lab runs on (--profile); on ES a case that declares "es" runs at that version (--gl),
    // the others at the lab's own lowest ES version.
    Profile profile = Profile::Core;
    // Where one is open: the lab binary that renders this runner's cases of it one after another, in one process
    // (lab_serve.h); renders of other binaries, and all where none is open, each start a process of their own.
    ServedLab* served = nullptr;
    // Added to the lab's environment: GSV_KNOWN_MISTAKE=<name> for a known C++ mistake's pictures (mistake_pictures.cpp).
    std::vector<std::string> extra_environment = {};

    // The case's image at the lab's size (one frame), and its arrays where the lab checks them; or with
    // `challenges` (one list of settings each), a timed run at the lab's timing size: one frame per challenge.
    LabRun render(const std::string& binary, const LabCases& lab, const GradeCase& c, const ProcessLimits& limits,
                  const std::vector<std::vector<std::string>>* challenges = nullptr) const;
    // What the lab's process gets in its environment: GSV_ROOT where root is set.
    std::vector<std::string> environment() const;
    // This runner with a process of its own for every render, as --one-process-per-case renders.
    LabRunner alone() const {
        LabRunner copy = *this;
        copy.served = nullptr;
        return copy;
    }
};

double median(std::vector<double> values);  // 0 for none

// The paths in a student process's messages as the student knows them: "labs/lab02_lic/streamline.glsl:12", not the
// grader's copy of the submission. `student_kit`: the copy of the kit the lab ran in (or the kit itself).
std::string as_student_sees(std::string text, const std::filesystem::path& student_kit);

// Tells the failure classes apart from how the process ended and the exit status the lab framework
// gives each (common/app/exit_status.h); Passed when it exited kExitOk.
CaseStatus classify(const ProcessResult& r, std::string& detail);

}  // namespace gsv
