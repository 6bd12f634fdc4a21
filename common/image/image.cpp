#include "common/image/image.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <system_error>

#include "common/core/error.h"

// The kit's single copy of stb_image and stb_image_write. Third-party code is not held to the
// kit's warning flags, so its warnings are silenced here and nowhere else.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#elif defined(_MSC_VER)
#pragma warning(push, 0)
#endif
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#elif defined(_MSC_VER)
#pragma warning(pop)
#endif

namespace gsv {
namespace {

std::size_t checked_pixel_count(int w, int h) {
    if (w < 0 || h < 0)
        throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " is negative");
    return static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
}

std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

}  // namespace

Image::Image(int w, int h) : width(w), height(h), rgba(checked_pixel_count(w, h) * 4, 0) {}

std::uint8_t* Image::at(int x, int y) {
    assert(x >= 0 && x < width && y >= 0 && y < height);
    return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
}

const std::uint8_t* Image::at(int x, int y) const {
    assert(x >= 0 && x < width && y >= 0 && y < height);
    return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
}

ImageF::ImageF(int w, int h) : width(w), height(h), rgba(checked_pixel_count(w, h) * 4, 0.0f) {}

float* ImageF::at(int x, int y) {
    assert(x >= 0 && x < width && y >= 0 && y < height);
    return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
}

const float* ImageF::at(int x, int y) const {
    assert(x >= 0 && x < width && y >= 0 && y < height);
    return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
}

// The file is read through a C++ stream rather than stbi_load's fopen so that std::filesystem
// paths work unchanged on every platform (fopen takes narrow strings only on Windows).
namespace {

Image decode_file(const std::filesystem::path& path, const std::string& what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::error_code ec;
        const bool exists = std::filesystem::exists(path, ec);
        throw Error("cannot read " + what + " " + quoted(path) + ": " + (exists ? "cannot open file" : "no such file"));
    }
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                           std::istreambuf_iterator<char>());
    if (in.bad()) throw Error("cannot read " + what + " " + quoted(path) + ": read error");
    if (bytes.empty()) throw Error("cannot read " + what + " " + quoted(path) + ": file is empty");
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw Error("cannot read " + what + " " + quoted(path) + ": file is larger than 2 GiB");

    int w = 0, h = 0, channels_in_file = 0;
    stbi_uc* pixels = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h,
                                            &channels_in_file, 4);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        throw Error("cannot read " + what + " " + quoted(path) + ": " + (reason ? reason : "unknown error"));
    }
    Image image(w, h);
    std::copy(pixels, pixels + image.rgba.size(), image.rgba.begin());
    stbi_image_free(pixels);
    return image;
}

}  // namespace

namespace {

template <class T>
void swap_rows(std::vector<T>& pixels, int width, int height) {
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(pixels.begin() + static_cast<std::ptrdiff_t>(y * row),
                         pixels.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                         pixels.begin() + static_cast<std::ptrdiff_t>((height - 1 - y) * row));
}

}  // namespace

void flip_rows(Image& image) { swap_rows(image.rgba, image.width, image.height); }
void flip_rows(ImageF& image) { swap_rows(image.rgba, image.width, image.height); }

Image read_png(const std::filesystem::path& path) { return decode_file(path, "PNG"); }

Image read_image(const std::filesystem::path& path) { return decode_file(path, "image"); }

namespace {

void append_to_stream(void* context, void* data, int size) {
    static_cast<std::ofstream*>(context)->write(static_cast<const char*>(data), size);
}

// Why `image` cannot be encoded, or empty when it can.
std::string unencodable(const Image& image) {
    if (image.empty())
        return "image is empty (" + std::to_string(image.width) + "x" + std::to_string(image.height) + ")";
    if (image.rgba.size() != checked_pixel_count(image.width, image.height) * 4)
        return "pixel buffer holds " + std::to_string(image.rgba.size()) + " bytes, " +
               std::to_string(image.width) + "x" + std::to_string(image.height) + " RGBA needs " +
               std::to_string(checked_pixel_count(image.width, image.height) * 4);
    return "";
}

void append_to_vector(void* context, void* data, int size) {
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

void write_png(const std::filesystem::path& path, const Image& image) {
    if (const std::string why = unencodable(image); !why.empty())
        throw Error("cannot write PNG " + quoted(path) + ": " + why);

    if (path.has_parent_path()) {
        std::error_code ec;
        std::filesystem::create_directories(path.parent_path(), ec);
        if (ec)
            throw Error("cannot write PNG " + quoted(path) + ": cannot create directory " +
                        quoted(path.parent_path()) + ": " + ec.message());
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot write PNG " + quoted(path) + ": cannot open file for writing");
    const int ok = stbi_write_png_to_func(append_to_stream, &out, image.width, image.height, 4,
                                          image.rgba.data(), image.width * 4);
    out.close();
    if (!ok) throw Error("cannot write PNG " + quoted(path) + ": PNG encoding failed");
    if (!out) throw Error("cannot write PNG " + quoted(path) + ": write error (disk full?)");
}

std::vector<std::uint8_t> encode_png(const Image& image) {
    if (const std::string why = unencodable(image); !why.empty()) throw Error("cannot encode PNG: " + why);
    std::vector<std::uint8_t> bytes;
    if (!stbi_write_png_to_func(append_to_vector, &bytes, image.width, image.height, 4, image.rgba.data(),
                                image.width * 4))
        throw Error("cannot encode PNG: encoding failed");
    return bytes;
}

std::vector<std::uint8_t> encode_jpeg(const Image& image, int quality) {
    if (const std::string why = unencodable(image); !why.empty()) throw Error("cannot encode JPEG: " + why);
    // JPEG has no alpha: the colour channels only, as the picture is seen.
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(image.width) * image.height * 3);
    for (std::size_t p = 0; p < rgb.size() / 3; ++p)
        for (int c = 0; c < 3; ++c) rgb[p * 3 + c] = image.rgba[p * 4 + c];
    std::vector<std::uint8_t> bytes;
    if (!stbi_write_jpg_to_func(append_to_vector, &bytes, image.width, image.height, 3, rgb.data(), std::clamp(quality, 1, 100)))
        throw Error("cannot encode JPEG: encoding failed");
    return bytes;
}

Image thumbnail(const Image& image, int longest) {
    const int side = std::max(image.width, image.height);
    if (image.empty() || side <= longest) return image;
    const int w = std::max(1, image.width * longest / side), h = std::max(1, image.height * longest / side);
    Image out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // The mean of the source pixels this one covers.
            const int x0 = x * image.width / w, x1 = std::max(x0 + 1, (x + 1) * image.width / w);
            const int y0 = y * image.height / h, y1 = std::max(y0 + 1, (y + 1) * image.height / h);
            unsigned sum[4] = {0, 0, 0, 0};
            for (int sy = y0; sy < y1; ++sy)
                for (int sx = x0; sx < x1; ++sx)
                    for (int c = 0; c < 4; ++c) sum[c] += image.at(sx, sy)[c];
            const unsigned n = static_cast<unsigned>((x1 - x0) * (y1 - y0));
            for (int c = 0; c < 4; ++c) out.at(x, y)[c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
        }
    return out;
}

Image to_rgba8(const ImageF& image) {
    Image out(image.width, image.height);
    const std::size_t pixel_count = out.rgba.size() / 4;
    for (std::size_t p = 0; p < pixel_count; ++p) {
        const float* src = image.rgba.data() + p * 4;
        std::uint8_t* dst = out.rgba.data() + p * 4;
        if (std::isnan(src[0]) || std::isnan(src[1]) || std::isnan(src[2]) || std::isnan(src[3])) {
            dst[0] = 255, dst[1] = 0, dst[2] = 255, dst[3] = 255;
            continue;
        }
        for (int c = 0; c < 4; ++c) {
            const float v = std::clamp(src[c], 0.0f, 1.0f);
            dst[c] = static_cast<std::uint8_t>(std::lround(v * 255.0f));
        }
    }
    return out;
}

}  // namespace gsv
