#pragma once
// Text on CPU images, for what a lecturer projects: the values and units of a legend, the labels of a comparison.
// Set in the kit's UI font (common/image/ui_font.h) at an integer pixel height, anti-aliased, blended over the
// image. UTF-8; a character the font lacks is drawn as the font's missing-glyph box.
#include "common/image/image.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace gsv {

using Rgba8 = std::array<std::uint8_t, 4>;

// The size text is set at: the font scaled so that its ascender-to-descender height is `pixel_height`.
struct TextSize {
    int width = 0;     // advance of the whole line, px
    int height = 0;    // ascender to descender, px
    int baseline = 0;  // from the top of the line, px
};

// Throws gsv::Error when no font is found (naming the paths tried) or `pixel_height` is below 1.
TextSize measure_text(const std::string& utf8, int pixel_height);

// Draws `utf8` with the top of its line at y and its first advance starting at x; pixels outside the image are
// skipped. Returns the x where the next character would go.
int draw_text(Image& image, int x, int y, const std::string& utf8, int pixel_height, Rgba8 color);

// Words packed into lines no wider than `width` px at `pixel_height` (a word wider than that gets a line of its
// own).
std::vector<std::string> wrap_text(const std::string& utf8, int width, int pixel_height);

// Fills the rectangle [x0, x1) x [y0, y1), clipped to the image, opaque.
void fill_rect(Image& image, int x0, int y0, int x1, int y1, Rgba8 color);

}  // namespace gsv
