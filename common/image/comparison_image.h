#pragma once
// Two renders of the same settings side by side with their difference, for `labXX compare`: the student's image,
// the reference's, and |yours - reference| per RGB channel, amplified by a power of two so that a difference of a
// few levels is visible on a projector, with the factor written above it.
#include "common/image/image.h"

#include <array>
#include <string>

namespace gsv {

struct ImageDifference {
    int max_rgb = 0;   // the largest difference of any R, G or B channel, 0..255
    double rmse = 0;   // over RGB, in levels (common/image/image_compare.h)
    long differing_pixels = 0;  // pixels with some RGB channel different
};
// Throws gsv::Error when the sizes differ.
ImageDifference image_difference(const Image& yours, const Image& reference);

// The largest power of two, at most 64, that keeps the largest difference within 255; 1 when the images agree.
int difference_factor(int max_rgb);

// |yours - reference| per RGB channel times `factor`, clamped, opaque: black where they agree.
Image amplified_difference(const Image& yours, const Image& reference, int factor);

struct ComparisonLayout {
    // yours, reference, difference and, where given, the known mistake's: [x0, y0, x1, y1] in the composite
    std::array<std::array<int, 4>, 4> panels{};
    int font_px = 0;
};

// A fourth panel: the picture of a known mistake that yours matches (common/app/known_mistake_pictures.h).
struct MistakePanel {
    Image picture;
    std::string label;
};

// The composite: a label over each panel (wrapped to its width), and one line of numbers under them.
Image compose_comparison(const Image& yours, const Image& reference, const std::string& yours_label,
                         const std::string& reference_label, ComparisonLayout* layout = nullptr,
                         const MistakePanel* mistake = nullptr);

}  // namespace gsv
