// Reading an APNG back, checking everything a viewer relies on: for the tests of the writer and for tools
// that check the animations the kit writes.
#include "common/image/animation.h"

#include "common/core/error.h"
#include "common/image/png_chunks.h"

#include <fstream>
#include <iterator>

namespace gsv {
namespace {

using png::Bytes;
using png::get_u16;
using png::get_u32;

// Checks one chunk in an APNG and adds what it says to `info`; throws the reason alone.
class ApngParser {
public:
    explicit ApngParser(ApngInfo& info) : info_(info) {}

    void add(const png::Chunk& chunk, bool first) {
        if (first != (chunk.type == "IHDR")) throw Error("IHDR is not the first chunk");
        if (chunk.type == "IHDR") ihdr(chunk.data);
        else if (chunk.type == "acTL") actl(chunk.data);
        else if (chunk.type == "fcTL") fctl(chunk.data);
        else if (chunk.type == "IDAT") idat(chunk.data);
        else if (chunk.type == "fdAT") fdat(chunk.data);
        else if (chunk.type == "IEND") finish();
    }

private:
    void need_size(const std::string& type, const Bytes& data, std::size_t size) {
        if (data.size() != size)
            throw Error(type + " holds " + std::to_string(data.size()) + " bytes, not " + std::to_string(size));
    }
    void next_sequence(const std::string& type, std::uint32_t sequence) {
        if (sequence != expected_sequence_)
            throw Error(type + " has sequence number " + std::to_string(sequence) + ", expected " +
                        std::to_string(expected_sequence_));
        ++expected_sequence_;
    }
    void frame_has_data() {
        if (!info_.frames.empty() && info_.frames.back().data.empty())
            throw Error("frame " + std::to_string(info_.frames.size() - 1) + " has no image data");
    }
    void ihdr(const Bytes& data) {
        need_size("IHDR", data, 13);
        info_.ihdr = data;
        info_.width = static_cast<int>(get_u32(&data[0]));
        info_.height = static_cast<int>(get_u32(&data[4]));
        if (info_.width <= 0 || info_.height <= 0) throw Error("IHDR gives a bad image size");
    }
    void actl(const Bytes& data) {
        if (actl_seen_ || idat_seen_) throw Error("acTL must come once, before the image data");
        need_size("acTL", data, 8);
        actl_seen_ = true;
        info_.num_frames = get_u32(&data[0]);
        info_.num_plays = get_u32(&data[4]);
        if (info_.num_frames == 0) throw Error("acTL gives 0 frames");
    }
    void fctl(const Bytes& data) {
        need_size("fcTL", data, 26);
        next_sequence("fcTL", get_u32(&data[0]));
        frame_has_data();
        ApngFrameInfo f;
        f.sequence = get_u32(&data[0]);
        f.width = static_cast<int>(get_u32(&data[4]));
        f.height = static_cast<int>(get_u32(&data[8]));
        f.x_offset = static_cast<int>(get_u32(&data[12]));
        f.y_offset = static_cast<int>(get_u32(&data[16]));
        f.delay = {get_u16(&data[20]), get_u16(&data[22])};
        f.dispose_op = data[24];
        f.blend_op = data[25];
        const std::string which = "frame " + std::to_string(info_.frames.size());
        if (f.width <= 0 || f.height <= 0 || f.x_offset < 0 || f.y_offset < 0 ||
            std::int64_t(f.x_offset) + f.width > info_.width || std::int64_t(f.y_offset) + f.height > info_.height)
            throw Error(which + "'s region lies outside the image");
        if (info_.frames.empty() && (f.width != info_.width || f.height != info_.height || f.x_offset || f.y_offset))
            throw Error("frame 0 does not cover the whole image");
        if (f.dispose_op > 2 || f.blend_op > 1) throw Error(which + " has an unknown dispose or blend op");
        info_.frames.push_back(std::move(f));
    }
    void idat(const Bytes& data) {
        if (!actl_seen_) throw Error("no acTL chunk before the image data: a plain PNG, not an animation");
        if (info_.frames.size() != 1) throw Error("the IDAT image is not frame 0 of the animation");
        idat_seen_ = true;
        info_.frames[0].data.insert(info_.frames[0].data.end(), data.begin(), data.end());
    }
    void fdat(const Bytes& data) {
        if (info_.frames.size() < 2 || !idat_seen_) throw Error("fdAT before the second frame's fcTL");
        if (data.size() < 4) throw Error("fdAT too short for its sequence number");
        next_sequence("fdAT", get_u32(&data[0]));
        ApngFrameInfo& f = info_.frames.back();
        f.data_sequences.push_back(get_u32(&data[0]));
        f.data.insert(f.data.end(), data.begin() + 4, data.end());
    }
    void finish() {
        if (!idat_seen_) throw Error("no image data (IDAT) at all");
        frame_has_data();
        if (info_.frames.size() != info_.num_frames)
            throw Error("acTL gives " + std::to_string(info_.num_frames) + " frames, the file holds " +
                        std::to_string(info_.frames.size()));
    }

    ApngInfo& info_;
    std::uint32_t expected_sequence_ = 0;
    bool actl_seen_ = false, idat_seen_ = false;
};

}  // namespace

ApngInfo parse_apng(const Bytes& bytes, const std::string& name) {
    ApngInfo info;
    try {
        ApngParser parser(info);
        const std::vector<png::Chunk> chunks = png::read_chunks(bytes);
        for (std::size_t i = 0; i < chunks.size(); ++i) parser.add(chunks[i], i == 0);
    } catch (const Error& e) {
        throw Error("'" + name + "' is not a valid APNG: " + e.what());
    }
    return info;
}

ApngInfo read_apng_info(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot read '" + path.string() + "': cannot open file");
    const Bytes bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw Error("cannot read '" + path.string() + "': read error");
    return parse_apng(bytes, path.string());
}

std::vector<std::uint8_t> apng_frame_as_png(const ApngInfo& info, std::size_t k) {
    if (k >= info.frames.size() || info.ihdr.size() != 13)
        throw Error("the animation has no frame " + std::to_string(k));
    const ApngFrameInfo& frame = info.frames[k];
    Bytes ihdr;
    png::put_u32(ihdr, static_cast<std::uint32_t>(frame.width));
    png::put_u32(ihdr, static_cast<std::uint32_t>(frame.height));
    ihdr.insert(ihdr.end(), info.ihdr.begin() + 8, info.ihdr.end());  // depth, colour type, ... as frame 0
    Bytes out(png::kSignature.begin(), png::kSignature.end());
    png::put_chunk(out, "IHDR", ihdr);
    png::put_chunk(out, "IDAT", frame.data);
    png::put_chunk(out, "IEND", {});
    return out;
}

}  // namespace gsv
