#pragma once
// The image half of a case's check: the student's image against the expected one (the reference's, rendered live or
// committed as a golden) under the case's tolerance. When they differ it says why, so the student knows what to fix:
// the starter's magenta (not done), one flat colour (blank), another case's committed golden (copied), or else a
// wrong image.
#include "common/image/image.h"
#include "grader/src/cases/cases.h"
#include "grader/src/core/grade_result.h"
#include "grader/src/run/lab_run.h"

#include <filesystem>
#include <functional>
#include <map>
#include <string>

namespace gsv {

// Where a copied image is looked for: the kit's committed goldens, and the pictures in the student's labs/.
class CopySearch {
public:
    // `student_kit`: the student's copy of the kit (its labs/), or the kit itself when its own labs are graded.
    CopySearch(std::filesystem::path kit, std::filesystem::path student_kit);
    // The public case whose committed golden `image` is pixel for pixel; empty if none.
    std::string golden_copied(const std::string& lab, const std::string& case_name, const Image& image);
    // A PNG in the student's labs/ whose pixels are `image`'s, as the student names it; empty if none.
    std::string picture_in_submission(const Image& image) const;

private:
    std::filesystem::path kit_, student_kit_;
    std::map<std::string, std::map<std::string, Image>> goldens_;  // lab -> case -> image
};

// Where the expected image is a golden rendered on another GL renderer than the student's labs ran on: the two
// renderers, and the `compare` command that shows a student the difference.
struct OtherRenderer {
    std::string golden, student, compare;
};

// Checks `actual` against `expected` and fills r.image, r.status and r.detail; a pass gives the case's points.
// Writes actual.png (and diff.png where they differ) into <out>/<lab>/<case>/. `draw` draws another case of the lab
// with the student's lab: an image that is another case's golden is a copy only when the lab does not draw it there.
// With `other_renderer`, a wrong image within the margin renderers differ by (cross_implementation_tolerance) is
// GpuMargin: "differs from the llvmpipe golden by a margin seen between GPUs", not wrong.
void check_image(const LabCases& lab, const GradeCase& c, const Image& actual, const Image& expected, bool live,
                 const std::filesystem::path& out, CopySearch& copies, const std::function<LabRun(const GradeCase&)>& draw,
                 const OtherRenderer* other_renderer, CaseResult& r);

}  // namespace gsv
