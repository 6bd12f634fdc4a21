#pragma once
// gsv-grade's exit statuses (grader/README.md), named where it ends and where a batch reads a submission's run.
namespace gsv {

enum GradeExit {
    kGradeOk = 0,         // grading ran, whatever the score (and --help, --version)
    kGradeFailed = 1,     // the score is under --fail-under; with --update-goldens, a golden the reference did not render
    kGradeNotGraded = 2,  // a usage or internal error, a mistake in a case file, a reference that failed: no grade
};

}  // namespace gsv
