#include "grader/src/judge/array_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gsv {
namespace {

bool same_non_finite(float a, float e) {
    if (std::isnan(a) || std::isnan(e)) return std::isnan(a) && std::isnan(e);
    return std::isinf(a) && std::isinf(e) && std::signbit(a) == std::signbit(e);
}

}  // namespace

ArrayDiff compare_array(const DataArray* actual, const ExpectedArray& expected, const ArrayTolerance& tolerance) {
    ArrayDiff d;
    d.name = expected.name;
    d.tolerance = tolerance;
    d.count = expected.count;
    d.components = expected.components;
    if (!actual) {
        d.problem = "the lab handed in no '" + expected.name + "' array";
        return d;
    }
    if (actual->count() != expected.count || actual->components != expected.components ||
        actual->values.size() != actual->count() * static_cast<std::size_t>(actual->components)) {
        d.problem = expected.name + ": " + with_commas(actual->count()) + " elements of " +
                    std::to_string(actual->components) + " components where the reference has " +
                    with_commas(expected.count) + " of " + std::to_string(expected.components);
        return d;
    }
    const std::size_t k = static_cast<std::size_t>(expected.components);
    d.compared = expected.held();
    for (std::size_t h = 0; h < d.compared; ++h) {
        const std::size_t element = expected.element(h);
        const float* a = actual->values.data() + element * k;
        const float* e = expected.values.data() + h * k;
        bool differs = false, non_finite = false;
        for (std::size_t c = 0; c < k; ++c) {
            if (std::isfinite(a[c]) && std::isfinite(e[c])) {
                const double diff = std::fabs(double(a[c]) - double(e[c]));
                d.max_abs_diff = std::max(d.max_abs_diff, diff);
                differs = differs || diff > tolerance.max_abs;
            } else if (!same_non_finite(a[c], e[c])) {
                differs = true;
                non_finite = non_finite || std::isfinite(e[c]);
            }
        }
        if (!differs) continue;
        if (d.differing == 0) {
            d.first = element;
            d.first_actual.assign(a, a + k);
            d.first_expected.assign(e, e + k);
        }
        ++d.differing;
        if (non_finite) ++d.non_finite;
    }
    return d;
}

}  // namespace gsv
