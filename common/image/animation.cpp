// APNG is PNG plus three chunk types: acTL (how many frames, how many plays), fcTL (a frame's size, offset
// and delay) and fdAT (a later frame's compressed data). So stb_image_write encodes each frame as a PNG and
// its IDAT data moves into fdAT chunks; only the chunk framing is ours.
#include "common/image/animation.h"

#include "common/core/error.h"
#include "common/image/png_chunks.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <system_error>

namespace gsv {
namespace {

using png::Bytes;
using png::put_chunk;
using png::put_u16;
using png::put_u32;

struct EncodedFrame {
    Bytes ihdr;
    std::vector<Bytes> idat;
};

EncodedFrame encode_frame(const Image& image) {
    EncodedFrame frame;
    for (auto& chunk : png::read_chunks(encode_png(image))) {
        if (chunk.type == "IHDR") frame.ihdr = std::move(chunk.data);
        else if (chunk.type == "IDAT") frame.idat.push_back(std::move(chunk.data));
    }
    return frame;
}

std::string size_text(const Image& image) { return std::to_string(image.width) + "x" + std::to_string(image.height); }

// Checked before any file is touched, so a bad call leaves nothing behind.
void check_frames(const std::vector<Image>& frames, ApngDelay delay) {
    if (frames.empty()) throw Error("an animation needs at least one frame");
    for (std::size_t k = 0; k < frames.size(); ++k) {
        if (frames[k].empty()) throw Error("frame " + std::to_string(k) + " is empty (" + size_text(frames[k]) + ")");
        if (frames[k].width != frames[0].width || frames[k].height != frames[0].height)
            throw Error("frame " + std::to_string(k) + " is " + size_text(frames[k]) + " but frame 0 is " +
                        size_text(frames[0]) + "; every frame must have the same size");
    }
    if (delay.num < 0 || delay.num > 65535 || delay.den < 0 || delay.den > 65535)
        throw Error("frame delay " + std::to_string(delay.num) + "/" + std::to_string(delay.den) +
                    " s does not fit APNG's 16-bit numerator and denominator");
}

Bytes fctl(std::uint32_t sequence, const Image& frame, ApngDelay delay) {
    Bytes data;
    put_u32(data, sequence);
    put_u32(data, static_cast<std::uint32_t>(frame.width));
    put_u32(data, static_cast<std::uint32_t>(frame.height));
    put_u32(data, 0);  // x and y offset: every frame covers the whole image
    put_u32(data, 0);
    put_u16(data, static_cast<std::uint32_t>(delay.num));
    put_u16(data, static_cast<std::uint32_t>(delay.den));
    data.push_back(0);  // dispose_op NONE: the next frame replaces this one whole anyway
    data.push_back(0);  // blend_op SOURCE: a translucent frame must not blend over the one before
    return data;
}

// One frame at a time, so memory holds one encoded frame and not the whole file.
void write_frames(std::ofstream& out, const std::vector<Image>& frames, ApngDelay delay) {
    std::uint32_t sequence = 0;  // fcTL and fdAT share one count, which is how readers order them
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const EncodedFrame encoded = encode_frame(frames[k]);
        Bytes bytes;
        if (k == 0) {
            bytes.assign(png::kSignature.begin(), png::kSignature.end());
            put_chunk(bytes, "IHDR", encoded.ihdr);
            Bytes actl;
            put_u32(actl, static_cast<std::uint32_t>(frames.size()));
            put_u32(actl, 0);  // plays: 0 loops forever
            put_chunk(bytes, "acTL", actl);
        }
        put_chunk(bytes, "fcTL", fctl(sequence++, frames[k], delay));
        for (const Bytes& idat : encoded.idat) {
            if (k == 0) {  // IDAT, so a plain PNG reader shows frame 0
                put_chunk(bytes, "IDAT", idat);
                continue;
            }
            Bytes fdat;
            put_u32(fdat, sequence++);
            fdat.insert(fdat.end(), idat.begin(), idat.end());
            put_chunk(bytes, "fdAT", fdat);
        }
        if (k + 1 == frames.size()) put_chunk(bytes, "IEND", {});
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    }
}

}  // namespace

ApngDelay apng_delay(double fps) {
    if (!(fps > 0 && fps <= 1000)) throw Error("frame rate " + std::to_string(fps) + " is out of range (0, 1000]");
    for (int scale : {1, 10, 100, 1000}) {
        const double den = fps * scale;
        if (std::abs(den - std::round(den)) < 1e-6 * scale && std::round(den) <= 65535)
            return {scale, static_cast<int>(std::round(den))};
    }
    return {static_cast<int>(std::lround(std::min(65535.0, 1000.0 / fps))), 1000};
}

void write_apng(const std::filesystem::path& path, const std::vector<Image>& frames, ApngDelay delay) {
    const std::string failed = "cannot write '" + path.string() + "': ";
    try {
        check_frames(frames, delay);
    } catch (const Error& e) {
        throw Error(failed + e.what());
    }
    std::error_code ec;
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path(), ec);
        if (ec) throw Error(failed + "cannot create its folder: " + ec.message());
    }
    // Written beside the target and renamed over it: nobody sees half an animation, and a failed run
    // leaves the previous file as it was.
    std::filesystem::path partial = path;
    partial += ".partial";
    try {
        std::ofstream out(partial, std::ios::binary | std::ios::trunc);
        if (!out) throw Error("cannot open " + partial.filename().string() + " for writing");
        write_frames(out, frames, delay);
        out.close();
        if (!out) throw Error("write error (disk full?)");
        std::filesystem::rename(partial, path, ec);
        if (ec) throw Error("cannot rename " + partial.filename().string() + " to it: " + ec.message());
    } catch (const Error& e) {
        std::filesystem::remove(partial, ec);
        throw Error(failed + e.what());
    }
}

}  // namespace gsv
