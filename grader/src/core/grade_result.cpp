#include "grader/src/core/grade_result.h"

namespace gsv {

bool DataCheck::passed() const {
    for (const auto& a : arrays)
        if (!a.within()) return false;
    return true;
}

double GradeReport::score() const {
    double total = 0;
    for (const auto& r : results) total += r.points;
    return total;
}

double GradeReport::max_score() const {
    double total = 0;
    for (const auto& r : results) total += r.max_points;
    return total;
}

}  // namespace gsv
