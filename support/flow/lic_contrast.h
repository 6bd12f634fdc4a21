#pragma once
// An optional contrast stretch for LIC images (labs 02 and 03), a lecturer's tool and no part of any TODO. LIC of
// white noise averages dozens of samples, so its grey levels crowd around the mean (the vortex street at length
// 30: a standard deviation of 7 of the 256 levels) and the streaks are hard to see on a projector. The common cure
// is a monotone tone curve applied after the convolution:
//   stretch   a linear map taking the 0.5th percentile of the image's grey to black and the 99.5th to white, the
//             1% of pixels beyond them clipped;
//   equalize  histogram equalisation: each level mapped to the share of pixels at or below it, so every grey
//             level is equally common.
// The curve is found on the CPU from the image's luminance and applied to every channel alike, so a grey image
// stays grey.
#include "common/core/enum_names.h"

#include <string>
#include <vector>

namespace gsv {

enum class LicContrast { Off, Stretch, Equalize };
inline constexpr EnumName<LicContrast> kLicContrastNames[] = {
    {LicContrast::Off, "off"}, {LicContrast::Stretch, "stretch"}, {LicContrast::Equalize, "equalize"}};

// A name of kLicContrastNames; any other throws gsv::Error listing them.
LicContrast lic_contrast_from_name(const std::string& name);

// The percentiles a stretch maps to black and white.
inline constexpr double kStretchLowShare = 0.005;
inline constexpr double kStretchHighShare = 0.995;
// Bins of the equalising histogram: finer than the 256 output levels, so no two output levels share a bin.
inline constexpr int kEqualizeBins = 1024;

// A monotone map of [low, high] onto [0, 1], piecewise linear through values[i] at
// low + i (high - low) / (values.size() - 1); below low it gives values.front(), above high values.back().
// An identity curve (no range to map: a constant image, an empty one) leaves every value as it is.
struct ToneCurve {
    float low = 0, high = 1;
    std::vector<float> values;  // at least two when not the identity
    bool identity() const { return values.size() < 2 || !(high > low); }
    float operator()(float grey) const;
};

// The curve that gives `grey` (the image's grey levels, any order; NaN and Inf are left out) the contrast asked
// for: the identity for Off, for an image with fewer than two distinct finite values, and for no values at all.
ToneCurve make_tone_curve(const std::vector<float>& grey, LicContrast contrast);

// A sweep compares images with one another; drawn each through a tone curve of its own, they would differ by their
// curves as well. Throws gsv::Error saying so, naming the contrast, unless it is Off.
void check_sweepable(LicContrast contrast);

}  // namespace gsv
