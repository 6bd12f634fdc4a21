#pragma once
// CPU-side images: what a lab reads back from the framebuffer, what the grader compares against a
// reference, and the PNG files both are stored in.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace gsv {

// 8-bit RGBA, 4 bytes per pixel, rows stored top to bottom (row 0 is the TOP row, as in PNG files;
// glReadPixels returns the bottom row first, so readback code must flip).
struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;

    Image() = default;
    Image(int w, int h);  // transparent black; throws gsv::Error on a negative size

    std::uint8_t* at(int x, int y);
    const std::uint8_t* at(int x, int y) const;
    bool empty() const { return width == 0 || height == 0; }
};

// Float RGBA, same layout as Image: for float render targets before they are quantised.
struct ImageF {
    int width = 0, height = 0;
    std::vector<float> rgba;

    ImageF() = default;
    ImageF(int w, int h);

    float* at(int x, int y);
    const float* at(int x, int y) const;
    bool empty() const { return width == 0 || height == 0; }
};

// Always returns RGBA whatever the file stores (gray, RGB, 16-bit, palette).
// Throws gsv::Error "cannot read PNG '<path>': <reason>" on a missing, corrupt or truncated file.
// Swaps the row order in place: images are stored top row first, GL textures and readbacks bottom row
// first.
void flip_rows(Image& image);
void flip_rows(ImageF& image);

Image read_png(const std::filesystem::path& path);
// The same for any format stb_image reads (PNG, JPEG, ...): photographs in data/.
Image read_image(const std::filesystem::path& path);

// Creates missing parent directories. Throws gsv::Error naming the path on failure.
void write_png(const std::filesystem::path& path, const Image& image);
// The bytes write_png would store: for containers built from PNG chunks (animated PNG).
std::vector<std::uint8_t> encode_png(const Image& image);

// JPEG bytes of the colour channels (quality 1..100): small pictures for a report a student downloads.
std::vector<std::uint8_t> encode_jpeg(const Image& image, int quality);
// The picture scaled down (area means) so its longer side is at most `longest`; as it is where it is no larger.
Image thumbnail(const Image& image, int longest);

// Clamps to [0,1] and rounds to the nearest of 256 levels. A pixel with a NaN in any channel
// becomes opaque magenta, so a shader bug shows up in the PNG instead of being clamped away.
Image to_rgba8(const ImageF& image);

}  // namespace gsv
