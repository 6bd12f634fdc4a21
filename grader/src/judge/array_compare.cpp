#include "grader/src/judge/array_compare.h"
#include "common/core/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gsv {
namespace {

bool same_non_finite(float a, float e) {
    if (std::isnan(a) || std::isnan(e)) return std::isnan(a) && std::isnan(e);
    return std::isinf(a) && std::isinf(e) && std::signbit(a) == std::signbit(e);
}

std::string number(float v, int digits) {
    if (std::isnan(v)) return "NaN";
    if (std::isinf(v)) return v > 0 ? "Inf" : "-Inf";
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(v));
    return text;
}

// "(0.1, 0.2, 0.3, 1)" for both sides; a component that differs but reads the same at 7 digits gets 9, so
// the two never look equal.
void element_texts(const std::vector<float>& a, const std::vector<float>& e, std::string& a_text, std::string& e_text) {
    a_text = e_text = "(";
    for (std::size_t c = 0; c < a.size() && c < e.size(); ++c) {
        std::string x = number(a[c], 7), y = number(e[c], 7);
        if (x == y && a[c] != e[c] && !std::isnan(a[c])) x = number(a[c], 9), y = number(e[c], 9);
        a_text += (c ? ", " : "") + x;
        e_text += (c ? ", " : "") + y;
    }
    a_text += ")";
    e_text += ")";
}

std::string percent(std::size_t part, std::size_t whole) {
    const double p = whole ? 100.0 * double(part) / double(whole) : 0.0;
    char text[32];
    std::snprintf(text, sizeof text, p >= 10 ? "%.0f" : "%.2g", p);
    return text;
}


}  // namespace

std::string with_commas(std::size_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

ExpectedArray expected_from(const DataArray& array) {
    ExpectedArray e;
    e.name = array.name;
    e.count = array.count();
    e.components = array.components;
    e.values = array.values;
    return e;
}

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

bool ArrayDiff::within() const {
    if (!problem.empty()) return false;
    // As for images: the slack lets exactly the written fraction of elements pass (0.29 * 100 is 28.999...).
    const double fraction = std::max(0.0, tolerance.max_differing_fraction);
    return double(differing) <= std::floor(fraction * double(compared) * (1.0 + 1e-12));
}

std::string ArrayDiff::summary() const {
    if (!problem.empty()) return problem;
    const std::string of = with_commas(compared) + (compared < count ? " sampled elements" : " elements");
    if (differing == 0)
        return name + ": all " + of + " within " + format_number(tolerance.max_abs) + " (max diff " +
               format_number(max_abs_diff) + ")";
    std::string a, e;
    element_texts(first_actual, first_expected, a, e);
    std::string line = name + ": " + with_commas(differing) + " of " + of + " (" + percent(differing, compared) +
                       "%) differ by more than " + format_number(tolerance.max_abs) + "; first at element " +
                       std::to_string(first) + ": " + a + " where the reference has " + e;
    if (non_finite > 0) line += "; " + with_commas(non_finite) + " of them NaN or Inf where the reference is finite";
    return line;
}

}  // namespace gsv
