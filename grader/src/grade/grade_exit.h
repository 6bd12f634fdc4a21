#pragma once
// gsv-grade's exit statuses (grader/README.md), named where it ends and where a batch reads a submission's run.
namespace gsv {

enum GradeExit {
    kGradeOk = 0,         // grading ran, whatever the score (and --help, --version)
    kGradeFailed = 1,     // the score is under --fail-under; with --update-goldens, a golden the reference did not render
    kGradeNotGraded = 2,  // a usage or internal error, a mistake in a case file, a submission that cannot be graded
    // The kit's fault, not the student's: a reference that failed, a kit build made from another checkout than --kit,
    // a kit file the build needs missing, a submission project that does not configure; no grade is given, and a
    // batch that sees it in its first submissions stops (grader/src/batch/batch.h).
    kGradeKitFault = 3,
};

}  // namespace gsv
