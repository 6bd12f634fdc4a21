// Reading the .flow file format of support/flow/flow_field.h: load_flow and load_flow_sequence.
#include "support/flow/flow_field.h"

#include "common/core/error.h"
#include "common/io/data_file.h"
#include "support/flow/flow_format.h"

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

const data_file::Format kFormat{"flow", kMagic, kVersion, "GSVFLOW 1 <width> <height>", 64};

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) { data_file::fail(kFormat, path, what); }

struct Header {
    int width = 0, height = 0, frames = 1;
};

// Opens the file and reads its header line, leaving `in` at the first velocity byte. Everything the
// header alone can show wrong, the size limit included, is refused here, before any velocity is read.
Header read_header(const std::filesystem::path& path, std::ifstream& in) {
    std::string line;
    const std::vector<std::string> fields = data_file::open_with_header(kFormat, path, in, &line);
    if (fields.size() != 4 && fields.size() != 5)
        fail(path, "header '" + data_file::printable(line) +
                       "' is not 'GSVFLOW 1 <width> <height>' or 'GSVFLOW 1 <width> <height> <frames>'");

    Header header;
    header.width = data_file::parse_count(kFormat, path, "width", fields[2], kMaxFlowSide);
    header.height = data_file::parse_count(kFormat, path, "height", fields[3], kMaxFlowSide);
    if (fields.size() == 5) header.frames = data_file::parse_count(kFormat, path, "frames", fields[4], kMaxFlowFrames);
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
    std::uint64_t found = 0;
    std::vector<FlowField> frames;
    for (int f = 0; f < header.frames; ++f) {
        FlowField field;
        field.width = header.width;
        field.height = header.height;
        data_file::read_floats(
            kFormat, path, in, values, field.velocity, found,
            [&](std::uint64_t read) { fail_short(path, header, expected, read); },
            [&](std::size_t i, float value) {
                fail(path, value_name(i, header.width, of_frame(f, header.frames)) + " is " + non_finite_kind(value));
            });
        frames.push_back(std::move(field));
    }
    data_file::refuse_trailing_bytes(kFormat, path, in, expected, "velocities");
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
