#pragma once
// A legend drawn beside an image, for `render --legend` and `animate --legend`: a vertical colour bar (the largest
// value at the top) with its ticks, named marks and unit in text, the colours that stand for no value below it,
// and, for a transfer function, its opacity as a curve beside the bar. The panel sits to the image's right; the
// image itself is copied unchanged.
#include "common/image/image.h"
#include "common/image/legend.h"

#include <array>
#include <vector>

namespace gsv {

// Where with_legend put things, in the composite's pixels: rectangles are [x0, x1) x [y0, y1).
struct LegendPlacement {
    std::array<int, 4> bar{};                  // the colour bar: row y0 is `max`, row y1 - 1 is `min`
    std::array<int, 4> opacity_plot{};         // where the opacity curve is drawn (empty without one)
    std::vector<std::array<int, 4>> swatches;  // one per special colour, in the legend's order
    int font_px = 0;                           // the text's pixel height

    // The value the bar shows at the centre of row `y`.
    double value_at_row(const Legend& legend, int y) const;
};

// The image with the legend's panel to its right, as tall as the image or as the legend needs. Throws gsv::Error
// for a legend check_legend refuses or when no font is found.
Image with_legend(const Image& image, const Legend& legend, LegendPlacement* placement = nullptr);

}  // namespace gsv
