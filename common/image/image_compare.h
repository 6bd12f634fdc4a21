#pragma once
// Comparing a rendered image with a reference the way web-platform-tests reftests do: a pixel
// "differs" when some channel is off by more than a per-channel tolerance, and the test passes
// when no more than a budget of pixels differ. GPUs and drivers legitimately disagree by a level
// or two on rasterisation edges and rounding, so exact equality would fail correct solutions.
//
// Where a picture is about positions (one-pixel particles, thin edges), GPUs also disagree on where a
// point lands: softpipe puts a one-pixel point about 1/8 px off llvmpipe. A neighbourhood radius r > 0
// matches each pixel with the best pixel within r (Chebyshev distance) of the other image, in both
// directions, the way the dEQP/VK-GL-CTS fuzzy compare does: a point moved by a pixel matches, a point
// that is missing (its golden pixel finds no match in the actual image) or has the wrong colour does not.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "common/image/image.h"

namespace gsv {

struct ImageTolerance {
    int max_channel_diff = 0;             // a pixel differs when any RGBA channel is off by more
    double max_differing_fraction = 0.0;  // of all pixels, allowed to differ
    // 0: each pixel against the pixel at the same place (exact placement). r > 0: a pixel's difference is
    // the larger of (a) the smallest max-channel difference between the actual pixel and any expected pixel
    // within r and (b) the same with actual and expected swapped.
    int neighbourhood = 0;
};
inline constexpr int kMaxNeighbourhood = 3;  // a case file's "neighbourhood" is 0..this

// "matched within 1 px" for a neighbourhood of 1; "" for 0 (exact placement).
std::string neighbourhood_text(int neighbourhood);

struct ImageDiff {
    bool size_mismatch = false;
    int actual_width = 0, actual_height = 0, expected_width = 0, expected_height = 0;

    int neighbourhood = 0;       // the tolerance's radius the differences below were matched within
    int max_channel_diff = 0;    // over all pixels and channels (RGBA), each pixel as matched within the radius
    long differing_pixels = 0;   // pixels whose (matched) difference > the tolerance's max_channel_diff
    long total_pixels = 0;
    double rmse = 0, psnr = 0;   // over RGB in [0,255]; psnr = +inf when RGB is identical
    double ssim = 1;             // ssim_luma(actual, expected)
    int diff_x0 = 0, diff_y0 = 0, diff_x1 = -1, diff_y1 = -1;  // inclusive box of differing pixels

    // Pixel counts by their largest (matched) channel difference, so within() can judge any tolerance with
    // the same neighbourhood, not only the one compare_images counted differing_pixels with.
    std::array<long, 256> pixels_by_max_diff{};

    // Passes when the sizes match and the number of pixels with some channel diff greater than
    // tolerance.max_channel_diff is at most floor(max_differing_fraction * total_pixels). Throws gsv::Error
    // when tolerance.neighbourhood is not the one compared with: compare again with that one.
    bool within(const ImageTolerance& tolerance) const;
    // Pixels whose difference is over max_channel_diff (the same neighbourhood).
    long pixels_over(int max_channel_diff) const;

    // One line, e.g. "max diff 37, 120 of 65536 px differ (0.18%) in [10,20]-[40,60],
    // PSNR 41.2 dB, SSIM 0.993", with ", matched within 1 px" after the pixel count for a neighbourhood;
    // for a size mismatch, both sizes.
    std::string summary() const;
};

// Throws nothing for a size mismatch: the result says so and within() fails. PSNR and SSIM are of the
// images as they are, whatever the neighbourhood.
ImageDiff compare_images(const Image& actual, const Image& expected,
                         const ImageTolerance& tolerance);

// Each pixel's difference as ImageTolerance describes it for `neighbourhood` (0: the largest channel difference
// at the same place), row by row. Throws gsv::Error when the sizes differ.
std::vector<std::uint8_t> matched_differences(const Image& actual, const Image& expected, int neighbourhood);

// Where the tolerance is exceeded, so that a 13-level error over a tolerance of 2 is as plain as a 200-level one:
// pixels over `max_channel_diff` (as matched within `neighbourhood`) bright, from red (just over) to yellow (over
// by 64 levels or more); the rest the expected image in dim grey, for where-am-I. Opaque. Throws gsv::Error when
// the sizes differ.
Image difference_heatmap(const Image& actual, const Image& expected, int max_channel_diff, int neighbourhood = 0);

// Mean SSIM (Wang, Bovik, Sheikh, Simoncelli 2004) of the luma Y = 0.299R + 0.587G + 0.114B;
// alpha is ignored. Throws gsv::Error when the sizes differ. See image_compare.cpp for the window
// and the border, which match scikit-image's structural_similarity.
double ssim_luma(const Image& a, const Image& b);

// True when every pixel has the same RGBA (vacuously for an empty image): a render that drew
// nothing, or only the clear colour.
bool is_blank(const Image& image);

// Pixels in the starter's not-done colour (gsv::kNotDoneRgb, magenta), lit or not: red and blue equal and bright,
// no green.
long not_done_pixels(const Image& image);

struct FloatStats {
    long nan_count = 0, inf_count = 0;  // counted per channel value
    float min = 0, max = 0;             // over finite values; 0 when there are none
};
FloatStats float_stats(const ImageF& image);

}  // namespace gsv
