#include "common/image/image_offset.h"

#include "common/core/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace gsv {
namespace {

// Mean absolute RGB difference of actual(x + sx, y + sy) and expected(x, y) over the interior both share at every
// shift of the search.
double mean_difference(const Image& actual, const Image& expected, int sx, int sy, int radius) {
    const int w = expected.width, h = expected.height;
    std::uint64_t sum = 0;
    for (int y = radius; y < h - radius; ++y) {
        const std::uint8_t* e = expected.rgba.data() + (std::size_t(y) * w + radius) * 4;
        const std::uint8_t* a = actual.rgba.data() + (std::size_t(y + sy) * w + radius + sx) * 4;
        for (int x = radius; x < w - radius; ++x, e += 4, a += 4)
            sum += std::uint64_t(std::abs(a[0] - e[0]) + std::abs(a[1] - e[1]) + std::abs(a[2] - e[2]));
    }
    const double pixels = double(w - 2 * radius) * double(h - 2 * radius);
    return double(sum) / pixels;
}

// The vertex of the parabola through (-1, left), (0, middle), (1, right), within half a pixel of 0; 0 where the three
// do not curve upwards (a flat or falling neighbourhood says nothing finer).
double parabola_vertex(double left, double middle, double right) {
    const double curvature = left - 2 * middle + right;
    if (!(curvature > 0)) return 0;
    return std::clamp(0.5 * (left - right) / curvature, -0.5, 0.5);
}

}  // namespace

bool ImageOffset::shifted() const {
    // Lining the picture up must explain the difference: at least a quarter of it goes away at the best shift.
    return measured && std::max(std::abs(dx), std::abs(dy)) > kMaxGlobalOffset && best < 0.75 * unshifted;
}

std::string ImageOffset::text() const {
    // Hundredths of a pixel: a float's residue (3.8e-06) is 0 here.
    const auto px = [](double v) { return format_number(std::abs(v) < 0.005 ? 0.0 : std::round(v * 100) / 100, 3); };
    std::string words;
    const auto side = [&](double v, const char* positive, const char* negative) {
        if (std::abs(v) < 0.05) return;
        words += (words.empty() ? "" : ", ") + px(std::abs(v)) + " " + (v > 0 ? positive : negative);
    };
    side(dx, "right", "left");
    side(dy, "down", "up");
    return "the whole picture is shifted by (" + px(dx) + ", " + px(dy) + ") px" + (words.empty() ? "" : " (" + words + ")") +
           " against the reference; a rasterizer moves it by at most " + px(kMaxGlobalOffset) + " px";
}

ImageOffset global_offset(const Image& actual, const Image& expected, int radius) {
    ImageOffset offset;
    if (actual.width != expected.width || actual.height != expected.height || radius < 1) return offset;
    if (expected.width < 2 * radius + 8 || expected.height < 2 * radius + 8) return offset;
    // One ring more than searched, measured only where the parabola at the search's edge needs it; every shift over
    // the same interior, so that they compare.
    const int search = radius + 1;
    const int side = 2 * search + 1;
    std::vector<double> d(std::size_t(side) * side, -1.0);
    const auto at = [&](int sx, int sy) {
        double& value = d[std::size_t(sy + search) * side + std::size_t(sx + search)];
        if (value < 0) value = mean_difference(actual, expected, sx, sy, search);
        return value;
    };
    offset.unshifted = at(0, 0);
    int bx = 0, by = 0;
    for (int sy = -radius; sy <= radius; ++sy)
        for (int sx = -radius; sx <= radius; ++sx)
            if (at(sx, sy) < at(bx, by)) bx = sx, by = sy;
    offset.best = at(bx, by);
    offset.measured = true;
    if (bx == 0 && by == 0 && offset.unshifted == 0) return offset;  // identical where it counts: no offset
    offset.dx = bx + parabola_vertex(at(bx - 1, by), at(bx, by), at(bx + 1, by));
    offset.dy = by + parabola_vertex(at(bx, by - 1), at(bx, by), at(bx, by + 1));
    return offset;
}

}  // namespace gsv
