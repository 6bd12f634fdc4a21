// The .flow file format of common/flow_field.h: load_flow and save_flow.
#include "common/flow_field.h"

#include "common/error.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

namespace gsv {
namespace {

// Velocities are stored as IEEE binary32 bit patterns; a host with another float format cannot share them.
static_assert(std::numeric_limits<float>::is_iec559 && sizeof(float) == 4, ".flow files need IEEE 754 floats");

constexpr int kMaxSide = 8192;
constexpr const char* kMagic = "GSVFLOW";
constexpr const char* kVersion = "1";
// Far longer than any valid header, short enough that a binary file is not read as one huge "line".
constexpr std::size_t kMaxHeaderLine = 64;
constexpr std::size_t kBytesPerTexel = 2 * sizeof(float);

std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
    throw Error("flow file " + quoted(path) + ": " + what);
}

// Header text is echoed in messages, so bytes that would garble a terminal are shown as '?'.
std::string printable(const std::string& text) {
    std::string shown = text;
    for (char& c : shown)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '?';
    return shown;
}

std::vector<std::string> split_spaces(const std::string& line) {
    std::vector<std::string> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t space = line.find(' ', start);
        fields.push_back(line.substr(start, space - start));
        if (space == std::string::npos) return fields;
        start = space + 1;
    }
}

// A side length written as plain decimal digits; anything else (sign, blank, overflow) is out of range.
int parse_side(const std::filesystem::path& path, const char* name, const std::string& text) {
    const bool digits = !text.empty() && text.size() <= 5 &&
                        std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int value = digits ? std::stoi(text) : -1;
    if (value < 1 || value > kMaxSide)
        fail(path, std::string(name) + " '" + printable(text) + "' is not in 1.." + std::to_string(kMaxSide));
    return value;
}

// Assembled from bytes so the host's own byte order never matters.
float float_from_little_endian(const unsigned char* bytes) {
    const std::uint32_t bits = std::uint32_t(bytes[0]) | std::uint32_t(bytes[1]) << 8 |
                               std::uint32_t(bytes[2]) << 16 | std::uint32_t(bytes[3]) << 24;
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

void float_to_little_endian(float value, unsigned char* bytes) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    for (int i = 0; i < 4; ++i) bytes[i] = static_cast<unsigned char>(bits >> (8 * i));
}

// "vx at texel (x, y)" for velocity value `index`; y counts from the bottom row as everywhere in the kit.
std::string value_name(std::size_t index, int width) {
    const std::size_t texel = index / 2;
    return std::string(index % 2 ? "vy" : "vx") + " at texel (" + std::to_string(texel % width) + ", " +
           std::to_string(texel / width) + ")";
}

const char* non_finite_kind(float value) { return std::isnan(value) ? "NaN" : "infinite"; }

}  // namespace

FlowField load_flow(const std::filesystem::path& path) {
    std::error_code ignored;
    // A directory opens as a stream on Linux and would then read as an empty file.
    if (std::filesystem::is_directory(path, ignored)) fail(path, "is a directory, not a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const bool exists = std::filesystem::exists(path, ignored);
        throw Error("cannot read flow file " + quoted(path) + ": " + (exists ? "cannot open file" : "no such file"));
    }

    std::string line;
    bool terminated = false;
    char c = 0;
    while (line.size() < kMaxHeaderLine && in.get(c)) {
        if (c == '\n') {
            terminated = true;
            break;
        }
        line += c;
    }
    if (in.bad()) fail(path, "read error");
    if (line.empty() && !terminated) fail(path, "file is empty");
    const std::vector<std::string> fields = split_spaces(line);
    if (fields[0] != kMagic) fail(path, "not a .flow file (it must start with 'GSVFLOW 1 <width> <height>')");
    if (!terminated)
        fail(path, "header line has no newline within its first " + std::to_string(kMaxHeaderLine) + " bytes");
    if (fields.size() >= 2 && fields[1] != kVersion)
        fail(path, "unsupported version '" + printable(fields[1]) + "' (this kit reads version 1)");
    if (fields.size() != 4)
        fail(path, "header '" + printable(line) + "' is not 'GSVFLOW 1 <width> <height>'");

    FlowField field;
    field.width = parse_side(path, "width", fields[2]);
    field.height = parse_side(path, "height", fields[3]);
    const std::size_t values = 2 * static_cast<std::size_t>(field.width) * static_cast<std::size_t>(field.height);
    const std::size_t expected = values * sizeof(float);

    // Read in chunks so a header that promises 512 MiB costs memory only for the bytes really there.
    std::vector<unsigned char> bytes;
    constexpr std::size_t kChunk = std::size_t(1) << 20;
    while (bytes.size() < expected && in) {
        const std::size_t old_size = bytes.size();
        bytes.resize(std::min(expected, old_size + kChunk));
        in.read(reinterpret_cast<char*>(bytes.data() + old_size), static_cast<std::streamsize>(bytes.size() - old_size));
        bytes.resize(old_size + static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) fail(path, "read error");
    if (bytes.size() < expected)
        fail(path, "expected " + std::to_string(expected) + " bytes of velocities, found " + std::to_string(bytes.size()) +
                       " (" + std::to_string(field.width) + "x" + std::to_string(field.height) + " texels, " +
                       std::to_string(kBytesPerTexel) + " bytes each)");
    in.ignore(std::numeric_limits<std::streamsize>::max());
    if (in.gcount() > 0)
        fail(path, std::to_string(in.gcount()) + " trailing bytes after the " + std::to_string(expected) +
                       " bytes of velocities");

    field.velocity.resize(values);
    for (std::size_t i = 0; i < values; ++i) {
        const float value = float_from_little_endian(bytes.data() + 4 * i);
        if (!std::isfinite(value)) fail(path, value_name(i, field.width) + " is " + non_finite_kind(value));
        field.velocity[i] = value;
    }
    return field;
}

void save_flow(const std::filesystem::path& path, const FlowField& field) {
    const auto refuse = [&](const std::string& what) {
        throw Error("save_flow " + quoted(path) + ": " + what);
    };
    if (field.width < 1 || field.width > kMaxSide || field.height < 1 || field.height > kMaxSide)
        refuse("size " + std::to_string(field.width) + "x" + std::to_string(field.height) + " is not in 1.." +
               std::to_string(kMaxSide) + " each way");
    const std::size_t values = 2 * static_cast<std::size_t>(field.width) * static_cast<std::size_t>(field.height);
    if (field.velocity.size() != values)
        refuse(std::to_string(field.velocity.size()) + " velocity values for " + std::to_string(field.width) + "x" +
               std::to_string(field.height) + " texels, which need " + std::to_string(values));

    const std::string header = std::string(kMagic) + " " + kVersion + " " + std::to_string(field.width) + " " +
                               std::to_string(field.height) + "\n";
    std::vector<unsigned char> bytes(header.begin(), header.end());
    bytes.resize(header.size() + values * sizeof(float));
    for (std::size_t i = 0; i < values; ++i) {
        if (!std::isfinite(field.velocity[i]))
            refuse(value_name(i, field.width) + " is " + non_finite_kind(field.velocity[i]));
        float_to_little_endian(field.velocity[i], bytes.data() + header.size() + 4 * i);
    }

    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot write flow file " + quoted(path));
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw Error("cannot write flow file " + quoted(path) + ": write error");
}

}  // namespace gsv
