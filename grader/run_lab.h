#pragma once
// Runs a lab binary headless on one case, in a working folder of its own, and reads back only what it
// may hand in: a PNG (decoded and size-checked), its JSON report's frame time (validated) and, for a lab
// whose cases check arrays, the arrays the report lists (grader/lab_arrays.h).
#include "common/gl/gl_version.h"
#include "common/image/image.h"
#include "common/io/data_array.h"
#include "grader/cases.h"
#include "grader/grade_result.h"
#include "grader/process.h"

#include <filesystem>
#include <optional>
#include <string>

namespace gsv {

struct LabRun {
    ProcessResult process;
    CaseStatus status = CaseStatus::Error;  // Passed: it ran, and image is set
    std::string detail;
    std::optional<Image> image;
    double median_ms = 0;  // by the grader's clock: the median time between the lab's frame marks
    std::vector<DataArray> arrays;  // read only for a lab that checks arrays, and not for timed runs
};

struct LabRunner {
    std::filesystem::path bin_dir;
    std::filesystem::path root;  // GSV_ROOT for the lab (a submission's kit view); empty: the binary's own
    bool student = false;        // its working folder is handed to the sandbox user
    // The GL profile the lab runs on (--profile); on ES a case that declares "es" runs at that version (--gl),
    // the others at the lab's own lowest ES version.
    Profile profile = Profile::Core;

    // The case's image at the lab's size (one frame), and its arrays where the lab checks them; or `timed`:
    // frames at the lab's timing size.
    LabRun render(const std::string& binary, const LabCases& lab, const GradeCase& c, bool timed,
                  const ProcessLimits& limits) const;
};

// The median of the times between consecutive frame marks (seconds, by the grader's clock), in ms. Throws
// gsv::Error unless there is one mark before the timed frames and one after each of `frames`.
double median_frame_ms(const std::vector<double>& marks, int frames);

// Tells the failure classes apart from how the process ended and the exit status the lab framework
// gives each (common/app/app.h); Passed when it exited 0.
CaseStatus classify(const ProcessResult& r, std::string& detail);

}  // namespace gsv
