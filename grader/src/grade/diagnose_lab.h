#pragma once
// A lab's failing cases diagnosed after they are graded (grader/src/diagnose/diagnosis.h): the known mistakes that
// explain them named in the report, and each explained row put on its mistake's TODO, before blame for needed TODOs
// is worked out (grader/src/judge/needs.h).
#include "grader/src/diagnose/diagnosis.h"
#include "grader/src/grade/mistake_pictures.h"
#include "grader/src/grade/session.h"

#include <cstddef>
#include <vector>

namespace gsv {

// A row that failed on its picture or numbers, with the render it was judged on and what it was judged against.
struct FailedRender {
    std::size_t row = 0;  // in the report's results
    const GradeCase* c = nullptr;
    LabRun student;
    ExpectedRender expected;
};

// A case the student's lab passed, with what it was judged against.
struct PassedRender {
    const GradeCase* c = nullptr;
    ExpectedRender expected;
};

// A lab's cases as the diagnosis sees them (only those the run diagnoses).
struct LabRenders {
    std::vector<FailedRender> failed;
    std::vector<PassedRender> passed;
};

// Whether the run diagnoses this case (--diagnose: public cases, or all).
bool diagnoses(const GradingSession& s, const GradeCase& c);

// Compares each failing render with every known mistake's render of its case, ranks the mistakes that explain them
// (only mistakes that agree with the cases the student passed: a mistake whose own picture fails a case the student's
// lab passed is not what the student did),
// marks the explained rows (CaseResult::mistake*, their mistake.png beside actual.png) and adds the lab's diagnosis
// (with its TODOs not started) to the report. A lab with no known mistakes, or a failure to make their pictures, is one
// line in report.diagnosis_note, and the grades stand as they are.
void diagnose_lab(GradingSession& s, MistakePictures& pictures, const LabCases& lab, std::size_t first,
                  const LabRenders& renders);

}  // namespace gsv
