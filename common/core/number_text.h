#pragma once
// Numbers typed by people and printed for them. Typed (command-line options, parameter values): the whole text must
// be one finite number, so "12abc", "", "nan" and "inf" are refused rather than read as 12, 0 or worse. Printed:
// %g, never std::to_string's six fixed decimals, which print a normal of 1e-9 as 0.
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace gsv {

inline std::optional<double> parse_finite_number(const std::string& text) {
    std::size_t used = 0;
    double value = 0;
    try {
        value = std::stod(text, &used);
    } catch (...) {
        return std::nullopt;
    }
    if (used != text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

// `significant` digits: 6 for people, 17 for every bit of a double (a value that must read back exactly).
inline std::string format_number(double value, int significant = 6) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", significant, value);
    return text;
}

}  // namespace gsv
