#include "common/io/data_file.h"

#include "common/core/error.h"
#include "common/io/little_endian.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <system_error>

namespace gsv::data_file {

void fail(const Format& format, const std::filesystem::path& path, const std::string& what) {
    throw Error(std::string(format.kind) + " file '" + path.string() + "': " + what);
}

void read_floats(const Format& format, const std::filesystem::path& path, std::ifstream& in, std::size_t count,
                 std::vector<float>& out, std::uint64_t& found, const std::function<void(std::uint64_t)>& short_read,
                 const std::function<void(std::size_t, float)>& non_finite) {
    constexpr std::size_t kChunkBytes = std::size_t(1) << 20;
    std::vector<unsigned char> chunk(std::min<std::size_t>(kChunkBytes, count * sizeof(float)));
    for (std::size_t done = 0; done < count;) {
        const std::size_t n = std::min(count - done, chunk.size() / sizeof(float));
        in.read(reinterpret_cast<char*>(chunk.data()), static_cast<std::streamsize>(n * sizeof(float)));
        found += static_cast<std::uint64_t>(in.gcount());
        if (in.bad()) fail(format, path, "read error");
        if (static_cast<std::size_t>(in.gcount()) < n * sizeof(float)) {
            short_read(found);
            fail(format, path, "ends early");  // short_read throws; this is never reached
        }
        for (std::size_t i = 0; i < n; ++i) {
            const float value = float_from_le_bytes(chunk.data() + 4 * i);
            if (!std::isfinite(value)) non_finite(done + i, value);
            out.push_back(value);
        }
        done += n;
    }
}

void refuse_trailing_bytes(const Format& format, const std::filesystem::path& path, std::ifstream& in,
                           std::uint64_t expected, const std::string& what) {
    in.ignore(std::numeric_limits<std::streamsize>::max());
    if (in.gcount() > 0)
        fail(format, path, std::to_string(in.gcount()) + " trailing bytes after the " + std::to_string(expected) +
                               " bytes of " + what);
}

std::string printable(const std::string& text) {
    std::string shown = text;
    for (char& c : shown)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '?';
    return shown;
}

std::vector<std::string> open_with_header(const Format& format, const std::filesystem::path& path, std::ifstream& in,
                                          std::string* line_out) {
    std::error_code ignored;
    // A directory opens as a stream on Linux and would then read as an empty file.
    if (std::filesystem::is_directory(path, ignored)) fail(format, path, "is a directory, not a file");
    in.open(path, std::ios::binary);
    if (!in) {
        const bool exists = std::filesystem::exists(path, ignored);
        throw Error(std::string("cannot read ") + format.kind + " file '" + path.string() +
                    "': " + (exists ? "cannot open file" : "no such file"));
    }
    std::string line;
    bool terminated = false;
    for (char c = 0; line.size() < format.max_header_bytes && in.get(c);) {
        if (c == '\n') {
            terminated = true;
            break;
        }
        line += c;
    }
    if (in.bad()) fail(format, path, "read error");
    if (line.empty() && !terminated) fail(format, path, "file is empty");
    std::vector<std::string> fields;
    for (std::size_t start = 0;;) {
        const std::size_t space = line.find(' ', start);
        fields.push_back(line.substr(start, space - start));
        if (space == std::string::npos) break;
        start = space + 1;
    }
    if (fields[0] != format.magic)
        fail(format, path, std::string("not a .") + format.kind + " file (it must start with '" + format.shape + "')");
    if (!terminated)
        fail(format, path, "header line has no newline within its first " + std::to_string(format.max_header_bytes) + " bytes");
    if (fields.size() >= 2 && fields[1] != format.version)
        fail(format, path, "unsupported version '" + printable(fields[1]) + "' (this kit reads version " + format.version + ")");
    if (line_out) *line_out = line;
    return fields;
}

int parse_count(const Format& format, const std::filesystem::path& path, const char* name, const std::string& text,
                int max) {
    const bool digits = !text.empty() && text.size() <= 5 &&
                        std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int value = digits ? std::stoi(text) : -1;
    if (value < 1 || value > max)
        fail(format, path, std::string(name) + " '" + printable(text) + "' is not in 1.." + std::to_string(max));
    return value;
}

}  // namespace gsv::data_file
