// Writing the .flow file format of support/flow/flow_field.h: save_flow and save_flow_sequence.
#include "support/flow/flow_field.h"

#include "common/core/error.h"
#include "support/flow/flow_format.h"

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace gsv {
namespace {

using namespace flow_format;
using Refuse = std::function<void(const std::string&)>;

bool side_ok(int side) { return side >= 1 && side <= kMaxFlowSide; }

std::string size_text(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

// Frame `frame` of `frames` against the size the header will declare: everything load_flow_sequence would
// refuse in it. A single field (frames == 1) keeps the messages save_flow always had.
void check_frame(const Refuse& refuse, const FlowField& field, int width, int height, int frame, int frames) {
    const std::string which = frames == 1 ? "" : "frame " + std::to_string(frame) + " has ";
    if (field.width != width || field.height != height)
        refuse("frame " + std::to_string(frame) + " is " + size_text(field.width, field.height) +
               ", not the sequence's " + size_text(width, height));
    const std::size_t values = 2 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (field.velocity.size() != values)
        refuse(which + std::to_string(field.velocity.size()) + " velocity values for " + size_text(width, height) +
               " texels, which need " + std::to_string(values));
    for (std::size_t i = 0; i < values; ++i)
        if (!std::isfinite(field.velocity[i]))
            refuse(value_name(i, width, of_frame(frame, frames)) + " is " + non_finite_kind(field.velocity[i]));
}

// Writes the header and the frames, already checked, a chunk at a time: a 512 MiB frame is never copied
// whole into bytes.
void write_flow(const std::filesystem::path& path, const std::string& header, const FlowField* frames,
                std::size_t count) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot write flow file " + quoted(path));
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    std::vector<unsigned char> chunk(kChunkBytes);
    for (const FlowField* field = frames; field != frames + count; ++field)
        for (std::size_t done = 0; done < field->velocity.size();) {
            const std::size_t n = std::min(field->velocity.size() - done, chunk.size() / sizeof(float));
            for (std::size_t i = 0; i < n; ++i) float_to_le_bytes(field->velocity[done + i], chunk.data() + 4 * i);
            out.write(reinterpret_cast<const char*>(chunk.data()), static_cast<std::streamsize>(n * sizeof(float)));
            done += n;
        }
    out.close();
    if (!out) throw Error("cannot write flow file " + quoted(path) + ": write error");
}

std::string header_line(int width, int height) {
    return std::string(kMagic) + " " + kVersion + " " + std::to_string(width) + " " + std::to_string(height);
}

}  // namespace

void save_flow(const std::filesystem::path& path, const FlowField& field) {
    const Refuse refuse = [&](const std::string& what) { throw Error("save_flow " + quoted(path) + ": " + what); };
    if (!side_ok(field.width) || !side_ok(field.height))
        refuse("size " + size_text(field.width, field.height) + " is not in 1.." + std::to_string(kMaxFlowSide) +
               " each way");
    check_frame(refuse, field, field.width, field.height, 0, 1);
    // The three-field header: a single field reads back with load_flow, as files always have.
    write_flow(path, header_line(field.width, field.height) + "\n", &field, 1);
}

void save_flow_sequence(const std::filesystem::path& path, const FlowSequence& sequence) {
    const Refuse refuse = [&](const std::string& what) {
        throw Error("save_flow_sequence " + quoted(path) + ": " + what);
    };
    const int frames = static_cast<int>(std::min<std::size_t>(sequence.frames.size(), kMaxFlowFrames + 1));
    if (frames < 1 || frames > kMaxFlowFrames)
        refuse("holds " + std::to_string(sequence.frames.size()) + " frames; a .flow file holds 1.." +
               std::to_string(kMaxFlowFrames));
    if (!side_ok(sequence.width) || !side_ok(sequence.height))
        refuse("size " + size_text(sequence.width, sequence.height) + " is not in 1.." + std::to_string(kMaxFlowSide) +
               " each way");
    const std::string too_big = over_size_limit(frames, sequence.width, sequence.height);
    if (!too_big.empty()) refuse(too_big);
    // Every frame is checked before the file is opened, so a refused save leaves no half-written file.
    for (int f = 0; f < frames; ++f)
        check_frame(refuse, sequence.frames[f], sequence.width, sequence.height, f, frames);
    // Always the four-field header, even for one frame: the file says it is a sequence.
    const std::string header = header_line(sequence.width, sequence.height) + " " + std::to_string(frames) + "\n";
    write_flow(path, header, sequence.frames.data(), sequence.frames.size());
}

}  // namespace gsv
