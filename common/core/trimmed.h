#pragma once
// A line without the white space around it (spaces, tabs, CR, form feed, vertical tab): what is quoted back from a
// file, or matched as a directive.
#include <string>
#include <string_view>

namespace gsv {

inline std::string trimmed(std::string_view text) {
    constexpr std::string_view kSpace = " \t\r\f\v";
    const std::size_t begin = text.find_first_not_of(kSpace);
    if (begin == std::string_view::npos) return "";
    return std::string(text.substr(begin, text.find_last_not_of(kSpace) - begin + 1));
}

}  // namespace gsv
