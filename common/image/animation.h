#pragma once
// Animated PNG (APNG): one file that browsers, Pillow and most viewers play, and that every plain PNG
// reader (stb_image, the grader) still opens as its first frame. Built from PNGs stb_image_write encodes.
#include "common/image/image.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

// Each frame shows for num/den seconds; both are 16-bit in the file.
struct ApngDelay {
    int num = 1, den = 20;
};
// Exact for rates such as 24, 12.5 or 29.97; otherwise the nearest millisecond. Throws unless 0 < fps <= 1000.
ApngDelay apng_delay(double fps);

// Writes `frames` (at least one, all the same size) as an APNG that loops forever. Throws gsv::Error
// "cannot write '<path>': <why>", naming the frame at fault; the file appears only once it is complete.
void write_apng(const std::filesystem::path& path, const std::vector<Image>& frames, ApngDelay delay);
inline void write_apng(const std::filesystem::path& path, const std::vector<Image>& frames, int delay_num,
                       int delay_den) {
    write_apng(path, frames, ApngDelay{delay_num, delay_den});
}

// What a reader finds in an APNG: for tests and tools that check the files the kit writes.
struct ApngFrameInfo {
    std::uint32_t sequence = 0;                  // the frame's fcTL
    std::vector<std::uint32_t> data_sequences;   // its fdAT chunks; empty for frame 0, which is IDAT
    int width = 0, height = 0, x_offset = 0, y_offset = 0;
    ApngDelay delay;
    int dispose_op = 0, blend_op = 0;
    std::vector<std::uint8_t> data;              // zlib stream: its IDAT or fdAT payloads joined
};

struct ApngInfo {
    int width = 0, height = 0;
    std::vector<std::uint8_t> ihdr;              // the IHDR payload, as stored
    std::uint32_t num_frames = 0, num_plays = 0; // acTL; 0 plays = forever
    std::vector<ApngFrameInfo> frames;
};

// Parses and checks the signature, every CRC, the chunk order, the sequence numbers (0, 1, 2... in file
// order), acTL's frame count and each frame's region. Throws gsv::Error "'<path>' is not a valid APNG: <why>".
ApngInfo read_apng_info(const std::filesystem::path& path);
ApngInfo parse_apng(const std::vector<std::uint8_t>& bytes, const std::string& name);

// Frame k as a PNG of its own (IHDR with the frame's size, its data as IDAT), for any PNG decoder.
std::vector<std::uint8_t> apng_frame_as_png(const ApngInfo& info, std::size_t k);

}  // namespace gsv
