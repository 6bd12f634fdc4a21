#pragma once
// How far a whole picture is moved against another: the shift that best lines `actual` up with `expected`. A
// tolerance with a neighbourhood forgives where a rasterizer puts each point (a fraction of a pixel, here and there);
// it must not forgive a picture that is all in the wrong place, a projection off by a pixel or two, which matches
// within the neighbourhood everywhere. Rasterizers disagree by fractions of a pixel (softpipe puts a point about 1/8 px
// off llvmpipe); a whole pixel is never theirs.
#include "common/image/image.h"

#include <string>

namespace gsv {

// The largest global offset (pixels, on either axis) correct renders may show against the reference. Measured over
// every public case on every implementation of the margin table (grader/README.md, "A shifted picture"): correct
// renders stay far under it, a picture moved by one pixel far over.
inline constexpr double kMaxGlobalOffset = 0.5;

struct ImageOffset {
    bool measured = false;  // false for images too small to shift, of other sizes, or without structure to line up
    double dx = 0, dy = 0;  // pixels, x to the right and y down: `actual` shows `expected` moved by (dx, dy)
    // Mean absolute RGB difference per pixel unshifted and at the best whole-pixel shift (0..765).
    double unshifted = 0, best = 0;
    // Whether the picture is moved by more than kMaxGlobalOffset and lining it up explains the difference better.
    bool shifted() const;
    // "the whole picture is shifted by (2, -2) px (2 right, 2 up)".
    std::string text() const;
};

// The shift of `actual` within `radius` pixels that minimises the mean absolute RGB difference with `expected`, over
// the pixels both share at every shift, refined to a fraction of a pixel by a parabola through the neighbouring shifts
// on each axis. An unshifted match is preferred where shifts tie (a flat picture, stripes), so only a real
// improvement moves the answer.
ImageOffset global_offset(const Image& actual, const Image& expected, int radius = 3);

}  // namespace gsv
