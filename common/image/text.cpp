#include "common/image/text.h"

#include "common/core/error.h"
#include "common/image/ui_font.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <sstream>
#include <vector>

// The kit's single copy of stb_truetype, private to this file (static functions), as stb_image is to image.cpp.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#elif defined(_MSC_VER)
#pragma warning(push, 0)
#endif
#define STBTT_STATIC
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb_truetype.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#elif defined(_MSC_VER)
#pragma warning(pop)
#endif

namespace gsv {
namespace {

struct Font {
    std::vector<unsigned char> bytes;
    stbtt_fontinfo info{};
};

std::unique_ptr<Font> load_font(const std::filesystem::path& path) {
    auto font = std::make_unique<Font>();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot read font '" + path.string() + "'");
    font->bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    const int offset = stbtt_GetFontOffsetForIndex(font->bytes.data(), 0);
    if (font->bytes.empty() || offset < 0 || !stbtt_InitFont(&font->info, font->bytes.data(), offset))
        throw Error("font '" + path.string() + "' is not a TrueType font stb_truetype can read");
    return font;
}

// Loaded once per process; a failure is not remembered, so the message comes again where text is asked for.
const Font& ui_font() {
    static std::mutex mutex;
    static std::unique_ptr<Font> font;
    const std::lock_guard<std::mutex> lock(mutex);
    if (!font) font = load_font(find_ui_font());
    return *font;
}

// UTF-8 to code points; a malformed byte becomes U+FFFD rather than ending the line.
std::vector<int> code_points(const std::string& text) {
    std::vector<int> out;
    for (std::size_t i = 0; i < text.size();) {
        const auto byte = static_cast<unsigned char>(text[i]);
        int length = byte < 0x80 ? 1 : (byte >> 5) == 0x6 ? 2 : (byte >> 4) == 0xE ? 3 : (byte >> 3) == 0x1E ? 4 : 0;
        if (length == 0 || i + static_cast<std::size_t>(length) > text.size()) {
            out.push_back(0xFFFD);
            ++i;
            continue;
        }
        int cp = length == 1 ? byte : byte & (0x7F >> length);
        bool ok = true;
        for (int k = 1; k < length; ++k) {
            const auto next = static_cast<unsigned char>(text[i + static_cast<std::size_t>(k)]);
            ok = ok && (next >> 6) == 0x2;
            cp = (cp << 6) | (next & 0x3F);
        }
        out.push_back(ok ? cp : 0xFFFD);
        i += ok ? static_cast<std::size_t>(length) : 1;
    }
    return out;
}

struct Scaled {
    float scale = 1;
    int ascent = 0, descent = 0;  // px, descent negative
};

Scaled scaled(const Font& font, int pixel_height) {
    if (pixel_height < 1) throw Error("text pixel height " + std::to_string(pixel_height) + " is below 1");
    Scaled s;
    s.scale = stbtt_ScaleForPixelHeight(&font.info, static_cast<float>(pixel_height));
    int ascent = 0, descent = 0, gap = 0;
    stbtt_GetFontVMetrics(&font.info, &ascent, &descent, &gap);
    s.ascent = static_cast<int>(std::ceil(ascent * s.scale));
    s.descent = static_cast<int>(std::floor(descent * s.scale));
    return s;
}

// Calls `glyph(cp, pen_x)` for each character at its pen position; returns the advance of the whole line.
template <class Glyph>
float lay_out(const Font& font, const Scaled& s, const std::vector<int>& text, Glyph glyph) {
    float pen = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        glyph(text[i], pen);
        int advance = 0, bearing = 0;
        stbtt_GetCodepointHMetrics(&font.info, text[i], &advance, &bearing);
        pen += advance * s.scale;
        if (i + 1 < text.size()) pen += s.scale * stbtt_GetCodepointKernAdvance(&font.info, text[i], text[i + 1]);
    }
    return pen;
}

void blend(std::uint8_t* pixel, Rgba8 color, int coverage) {
    const float a = (coverage / 255.0f) * (color[3] / 255.0f);
    for (int c = 0; c < 3; ++c) pixel[c] = static_cast<std::uint8_t>(std::lround(pixel[c] * (1 - a) + color[c] * a));
    pixel[3] = static_cast<std::uint8_t>(std::lround(255 * (a + (pixel[3] / 255.0f) * (1 - a))));
}

}  // namespace

TextSize measure_text(const std::string& utf8, int pixel_height) {
    const Font& font = ui_font();
    const Scaled s = scaled(font, pixel_height);
    const float width = lay_out(font, s, code_points(utf8), [](int, float) {});
    return {static_cast<int>(std::ceil(width)), s.ascent - s.descent, s.ascent};
}

int draw_text(Image& image, int x, int y, const std::string& utf8, int pixel_height, Rgba8 color) {
    const Font& font = ui_font();
    const Scaled s = scaled(font, pixel_height);
    std::vector<unsigned char> coverage;
    const float width = lay_out(font, s, code_points(utf8), [&](int cp, float pen) {
        // Each glyph placed at its sub-pixel position, so spacing does not drift by rounding character by character.
        const float shift = pen - std::floor(pen);
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        stbtt_GetCodepointBitmapBoxSubpixel(&font.info, cp, s.scale, s.scale, shift, 0, &x0, &y0, &x1, &y1);
        const int w = x1 - x0, h = y1 - y0;
        if (w <= 0 || h <= 0) return;
        coverage.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
        stbtt_MakeCodepointBitmapSubpixel(&font.info, coverage.data(), w, h, w, s.scale, s.scale, shift, 0, cp);
        const int left = x + static_cast<int>(std::floor(pen)) + x0, top = y + s.ascent + y0;
        for (int row = 0; row < h; ++row) {
            const int py = top + row;
            if (py < 0 || py >= image.height) continue;
            for (int col = 0; col < w; ++col) {
                const int px = left + col;
                const int c = coverage[static_cast<std::size_t>(row) * static_cast<std::size_t>(w) + static_cast<std::size_t>(col)];
                if (px >= 0 && px < image.width && c > 0) blend(image.at(px, py), color, c);
            }
        }
    });
    return x + static_cast<int>(std::ceil(width));
}

std::vector<std::string> wrap_text(const std::string& utf8, int width, int pixel_height) {
    std::vector<std::string> lines;
    std::istringstream words(utf8);
    std::string line, word;
    while (words >> word) {
        const std::string longer = line.empty() ? word : line + " " + word;
        if (!line.empty() && measure_text(longer, pixel_height).width > width) {
            lines.push_back(line);
            line = word;
        } else {
            line = longer;
        }
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

void fill_rect(Image& image, int x0, int y0, int x1, int y1, Rgba8 color) {
    x0 = std::max(x0, 0), y0 = std::max(y0, 0);
    x1 = std::min(x1, image.width), y1 = std::min(y1, image.height);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) std::copy(color.begin(), color.end(), image.at(x, y));
}

}  // namespace gsv
