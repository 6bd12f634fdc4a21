// Reading the .height file format of common/height_field.h: load_height_field.
#include "common/height_field.h"

#include "common/error.h"
#include "common/height_format.h"
#include "common/little_endian.h"

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

namespace gsv {
namespace {

using namespace height_format;

// Far longer than any valid header, short enough that a binary file is not read as one huge "line".
constexpr std::size_t kMaxHeaderLine = 128;
constexpr const char* kHeaderShape = "GSVHEIGHT 1 <width> <height> <dx_m> <dy_m>";

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
    throw Error("height file " + quoted(path) + ": " + what);
}

// Header text is echoed in messages, so bytes that would garble a terminal are shown as '?'.
std::string printable(std::string text) {
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '?';
    return text;
}

std::vector<std::string> split_spaces(const std::string& line) {
    std::vector<std::string> fields;
    for (std::size_t start = 0;;) {
        const std::size_t space = line.find(' ', start);
        fields.push_back(line.substr(start, space - start));
        if (space == std::string::npos) return fields;
        start = space + 1;
    }
}

// Plain decimal digits only: a sign, a blank or an overflow is out of range rather than read as something.
int parse_side(const std::filesystem::path& path, const char* name, const std::string& text) {
    const bool digits = !text.empty() && text.size() <= 5 &&
                        std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int value = digits ? std::stoi(text) : -1;
    if (value < 1 || value > kMaxHeightSide)
        fail(path, std::string(name) + " '" + printable(text) + "' is not in 1.." + std::to_string(kMaxHeightSide));
    return value;
}

double parse_metres(const std::filesystem::path& path, const char* name, const std::string& text) {
    const std::optional<double> value = parse_spacing(text);
    if (!value) fail(path, std::string(name) + " '" + printable(text) + "' is not a positive, finite number of metres");
    return *value;
}

// Opens the file and reads its header line, leaving `in` at the first height byte. Everything the header
// alone can show wrong is refused here, before any height is read or allocated.
HeightField read_header(const std::filesystem::path& path, std::ifstream& in) {
    std::error_code ignored;
    // A directory opens as a stream on Linux and would then read as an empty file.
    if (std::filesystem::is_directory(path, ignored)) fail(path, "is a directory, not a file");
    in.open(path, std::ios::binary);
    if (!in) {
        const bool exists = std::filesystem::exists(path, ignored);
        throw Error("cannot read height file " + quoted(path) + ": " + (exists ? "cannot open file" : "no such file"));
    }

    std::string line;
    bool terminated = false;
    for (char c = 0; line.size() < kMaxHeaderLine && in.get(c);) {
        if (c == '\n') {
            terminated = true;
            break;
        }
        line += c;
    }
    if (in.bad()) fail(path, "read error");
    if (line.empty() && !terminated) fail(path, "file is empty");
    const std::vector<std::string> fields = split_spaces(line);
    if (fields[0] != kMagic) fail(path, std::string("not a .height file (it must start with '") + kHeaderShape + "')");
    if (!terminated)
        fail(path, "header line has no newline within its first " + std::to_string(kMaxHeaderLine) + " bytes");
    if (fields.size() >= 2 && fields[1] != kVersion)
        fail(path, "unsupported version '" + printable(fields[1]) + "' (this kit reads version 1)");
    if (fields.size() != 6) fail(path, "header '" + printable(line) + "' is not '" + kHeaderShape + "'");

    HeightField field;
    field.width = parse_side(path, "width", fields[2]);
    field.height = parse_side(path, "height", fields[3]);
    field.dx_m = parse_metres(path, "dx_m", fields[4]);
    field.dy_m = parse_metres(path, "dy_m", fields[5]);
    return field;
}

// Reads the heights chunk by chunk, so the vector grows only with bytes really in the file, then refuses
// anything after them.
void read_heights(const std::filesystem::path& path, std::ifstream& in, HeightField& field) {
    const std::size_t count = static_cast<std::size_t>(field.width) * static_cast<std::size_t>(field.height);
    const std::uint64_t expected = height_bytes(field.width, field.height);
    std::vector<unsigned char> chunk(std::min<std::size_t>(kChunkBytes, count * sizeof(float)));
    std::uint64_t found = 0;
    for (std::size_t done = 0; done < count;) {
        const std::size_t n = std::min(count - done, chunk.size() / sizeof(float));
        in.read(reinterpret_cast<char*>(chunk.data()), static_cast<std::streamsize>(n * sizeof(float)));
        found += static_cast<std::uint64_t>(in.gcount());
        if (in.bad()) fail(path, "read error");
        if (static_cast<std::size_t>(in.gcount()) < n * sizeof(float))
            fail(path, "expected " + std::to_string(expected) + " bytes of heights, found " + std::to_string(found) +
                           " (" + std::to_string(field.width) + "x" + std::to_string(field.height) +
                           " samples, 4 bytes each)");
        field.heights.resize(done + n);
        for (std::size_t i = 0; i < n; ++i) {
            const float value = float_from_le_bytes(chunk.data() + 4 * i);
            if (!std::isfinite(value))
                fail(path, "height at " + sample_name(done + i, field.width) + " is " + non_finite_kind(value));
            field.heights[done + i] = value;
        }
        done += n;
    }
    in.ignore(std::numeric_limits<std::streamsize>::max());
    if (in.gcount() > 0)
        fail(path, std::to_string(in.gcount()) + " trailing bytes after the " + std::to_string(expected) +
                       " bytes of heights");
}

}  // namespace

HeightField load_height_field(const std::filesystem::path& path) {
    std::ifstream in;
    HeightField field = read_header(path, in);
    read_heights(path, in, field);
    return field;
}

}  // namespace gsv
