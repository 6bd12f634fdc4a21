#pragma once
// What the kit's binary data files (.flow, .height) share: an ASCII header line
// "<MAGIC> <version> <fields...>\n" before little-endian float32 values, read and checked the same way,
// with one-line errors that name the file.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace gsv::data_file {

struct Format {
    const char* kind;    // "flow": messages say "flow file '<path>': ..."
    const char* magic;   // "GSVFLOW"
    const char* version; // "1"
    const char* shape;   // the header as a reader should write it, for messages
    std::size_t max_header_bytes;  // far longer than a valid header, short enough that binary is not a "line"
};

// Throws gsv::Error "<kind> file '<path>': <what>".
[[noreturn]] void fail(const Format& format, const std::filesystem::path& path, const std::string& what);

// Header text echoed in a message: bytes that would garble a terminal are shown as '?'.
std::string printable(const std::string& text);

// Opens `path` into `in` and reads its header line, leaving `in` at the first data byte. Refuses a folder,
// a missing or unreadable file, an empty one, another magic, no newline within max_header_bytes, and
// another version. Returns the fields, split at single spaces (magic and version first; a doubled space
// gives an empty field, which the caller's parse then refuses).
std::vector<std::string> open_with_header(const Format& format, const std::filesystem::path& path, std::ifstream& in,
                                          std::string* line = nullptr);

// Reads `count` little-endian float32 values from `in` into `out` (appended), chunk by chunk, so a header that
// promises a gigabyte costs memory only for the bytes really there. `found` counts the data bytes read so far,
// across calls. On a short read it calls short_read(found), for a NaN or Inf non_finite(index in this call, value);
// both must throw (a one-line gsv::Error naming the file). A read error fails here.
void read_floats(const Format& format, const std::filesystem::path& path, std::ifstream& in, std::size_t count,
                 std::vector<float>& out, std::uint64_t& found, const std::function<void(std::uint64_t)>& short_read,
                 const std::function<void(std::size_t, float)>& non_finite);

// Refuses anything after the data: "<n> trailing bytes after the <expected> bytes of <what>".
void refuse_trailing_bytes(const Format& format, const std::filesystem::path& path, std::ifstream& in,
                           std::uint64_t expected, const std::string& what);

// A count written as plain decimal digits in 1..max: a sign, a blank or an overflow is out of range
// rather than read as something.
int parse_count(const Format& format, const std::filesystem::path& path, const char* name, const std::string& text,
                int max);

}  // namespace gsv::data_file
