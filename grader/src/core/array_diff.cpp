#include "grader/src/core/array_diff.h"
#include "common/core/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gsv {
namespace {

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
