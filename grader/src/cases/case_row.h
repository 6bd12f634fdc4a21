#pragma once
// A case's row before anything ran: its lab, name, TODO, description, visibility, settings and points. The grader
// (grade/session.cpp), the diagnosis (diagnose/diagnosis.cpp) and the browser page's self-check
// (app/page_self_check.cpp) start every row from it.
#include "grader/src/cases/cases.h"
#include "grader/src/core/grade_result.h"

namespace gsv {

CaseResult case_row(const LabCases& lab, const GradeCase& c);

}  // namespace gsv
