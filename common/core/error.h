#pragma once
// Every user-facing failure in the kit is a gsv::Error carrying one line that names the file, line,
// option or value at fault; the lab's main() prints it and exits non-zero.
#include <stdexcept>
#include <string>

namespace gsv {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// A GL feature the context does not offer; exits with its own status so a grader can tell it apart.
class UnsupportedError : public Error {
public:
    using Error::Error;
};

}  // namespace gsv
