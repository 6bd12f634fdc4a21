// Reading the .flow file format of common/flow_field.h: load_flow and load_flow_sequence.
#include "common/flow_field.h"

#include "common/error.h"
#include "common/flow_format.h"

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <limits>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace gsv {
namespace {

using namespace flow_format;

// Far longer than any valid header, short enough that a binary file is not read as one huge "line".
constexpr std::size_t kMaxHeaderLine = 64;

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

// A side length or frame count written as plain decimal digits; anything else (sign, blank, overflow) is
// out of range.
int parse_count(const std::filesystem::path& path, const char* name, const std::string& text, int max) {
    const bool digits = !text.empty() && text.size() <= 5 &&
                        std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int value = digits ? std::stoi(text) : -1;
    if (value < 1 || value > max)
        fail(path, std::string(name) + " '" + printable(text) + "' is not in 1.." + std::to_string(max));
    return value;
}

struct Header {
    int width = 0, height = 0, frames = 1;
};

// Opens the file and reads its header line, leaving `in` at the first velocity byte. Everything the
// header alone can show wrong, the size limit included, is refused here, before any velocity is read.
Header read_header(const std::filesystem::path& path, std::ifstream& in) {
    std::error_code ignored;
    // A directory opens as a stream on Linux and would then read as an empty file.
    if (std::filesystem::is_directory(path, ignored)) fail(path, "is a directory, not a file");
    in.open(path, std::ios::binary);
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
    if (fields.size() != 4 && fields.size() != 5)
        fail(path, "header '" + printable(line) +
                       "' is not 'GSVFLOW 1 <width> <height>' or 'GSVFLOW 1 <width> <height> <frames>'");

    Header header;
    header.width = parse_count(path, "width", fields[2], kMaxFlowSide);
    header.height = parse_count(path, "height", fields[3], kMaxFlowSide);
    if (fields.size() == 5) header.frames = parse_count(path, "frames", fields[4], kMaxFlowFrames);
    const std::string too_big = over_size_limit(header.frames, header.width, header.height);
    if (!too_big.empty()) fail(path, too_big);
    return header;
}

// What a file that ends after `found` of the `expected` bytes of velocities lacks. A single field keeps
// the message it always had; in a sequence, the frame where the bytes ran out is what helps find the fault.
[[noreturn]] void fail_short(const std::filesystem::path& path, const Header& header, std::uint64_t expected,
                             std::uint64_t found) {
    const std::string texels = std::to_string(header.width) + "x" + std::to_string(header.height) + " texels, " +
                               std::to_string(kBytesPerTexel) + " bytes each";
    if (header.frames == 1)
        fail(path, "expected " + std::to_string(expected) + " bytes of velocities, found " + std::to_string(found) +
                       " (" + texels + ")");
    const std::uint64_t frame_bytes = velocity_bytes(1, header.width, header.height);
    const std::uint64_t frame = found / frame_bytes, into = found % frame_bytes;
    const std::string where =
        into == 0 ? "they end before frame " + std::to_string(frame)
                  : "they end in frame " + std::to_string(frame) + ", after " + std::to_string(into) + " of its " +
                        std::to_string(frame_bytes) + " bytes";
    fail(path, "expected " + std::to_string(expected) + " bytes of velocities for " + std::to_string(header.frames) +
                   " frames, found " + std::to_string(found) + ": " + where + " (frames count from 0; " + texels +
                   ")");
}

// Reads the velocities after the header, chunk by chunk, so a header that promises a gigabyte costs memory
// only for the bytes really there; then refuses anything after them.
std::vector<FlowField> read_frames(const std::filesystem::path& path, std::ifstream& in, const Header& header) {
    const std::size_t values = 2 * static_cast<std::size_t>(header.width) * static_cast<std::size_t>(header.height);
    const std::uint64_t expected = velocity_bytes(header.frames, header.width, header.height);
    std::vector<unsigned char> chunk(std::min<std::size_t>(kChunkBytes, values * sizeof(float)));
    std::uint64_t found = 0;
    std::vector<FlowField> frames;
    for (int f = 0; f < header.frames; ++f) {
        FlowField field;
        field.width = header.width;
        field.height = header.height;
        for (std::size_t done = 0; done < values;) {
            const std::size_t count = std::min(values - done, chunk.size() / sizeof(float));
            in.read(reinterpret_cast<char*>(chunk.data()), static_cast<std::streamsize>(count * sizeof(float)));
            found += static_cast<std::uint64_t>(in.gcount());
            if (in.bad()) fail(path, "read error");
            if (static_cast<std::size_t>(in.gcount()) < count * sizeof(float))
                fail_short(path, header, expected, found);
            field.velocity.resize(done + count);
            for (std::size_t i = 0; i < count; ++i) {
                const float value = float_from_little_endian(chunk.data() + 4 * i);
                if (!std::isfinite(value))
                    fail(path, value_name(done + i, header.width, of_frame(f, header.frames)) + " is " +
                                   non_finite_kind(value));
                field.velocity[done + i] = value;
            }
            done += count;
        }
        frames.push_back(std::move(field));
    }
    in.ignore(std::numeric_limits<std::streamsize>::max());
    if (in.gcount() > 0)
        fail(path, std::to_string(in.gcount()) + " trailing bytes after the " + std::to_string(expected) +
                       " bytes of velocities");
    return frames;
}

}  // namespace

FlowField load_flow(const std::filesystem::path& path) {
    std::ifstream in;
    const Header header = read_header(path, in);
    // Refused before reading: taking frame 0 of a sequence would silently freeze a time-varying flow.
    if (header.frames > 1)
        fail(path, "holds " + std::to_string(header.frames) +
                       " frames; a single field is needed (lab 03 reads sequences)");
    return std::move(read_frames(path, in, header).front());
}

FlowSequence load_flow_sequence(const std::filesystem::path& path) {
    std::ifstream in;
    const Header header = read_header(path, in);
    FlowSequence sequence;
    sequence.width = header.width;
    sequence.height = header.height;
    sequence.frames = read_frames(path, in, header);
    return sequence;
}

}  // namespace gsv
