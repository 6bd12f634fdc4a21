#pragma once
// Numbers typed by people (command-line options, parameter values): the whole text must be one finite
// number, so "12abc", "", "nan" and "inf" are refused rather than read as 12, 0 or worse.
#include <cmath>
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

}  // namespace gsv
