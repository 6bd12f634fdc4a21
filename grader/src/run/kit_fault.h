#pragma once
// What stops a grading run for the kit's own reason, never the student's: a kit build made from another checkout than
// --kit, a file the submission's build needs missing from the kit. gsv-grade says it in one line with what to do and
// exits kGradeKitFault (grade_exit.h); no grade is given, and a batch that sees it stops (grader/src/batch/batch.h).
#include "common/core/error.h"

#include <filesystem>

namespace gsv {

class KitFault : public Error {
public:
    using Error::Error;
};

// Before any submission is built: the kit build at `kit_build` was made from `kit` (the same checkout, by its real
// path), and holds every file a submission's build reads from the kit. Throws KitFault naming what is wrong and how
// to fix it.
void check_kit_for_submissions(const std::filesystem::path& kit, const std::filesystem::path& kit_build);

}  // namespace gsv
