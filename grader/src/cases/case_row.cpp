#include "grader/src/cases/case_row.h"

namespace gsv {

CaseResult case_row(const LabCases& lab, const GradeCase& c) {
    CaseResult r;
    r.lab = lab.lab;
    r.name = c.name;
    r.todo = c.todo;
    r.description = c.description;
    r.visibility = c.visibility;
    r.settings = c.settings;
    r.max_points = c.points;
    return r;
}

}  // namespace gsv
