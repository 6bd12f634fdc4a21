#include "catch.hpp"

#include "common/core/error.h"
#include "support/flow/lic_contrast.h"
#include "support/flow/noise.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using gsv::LicContrast;
using gsv::make_tone_curve;
using gsv::ToneCurve;

namespace {

// Grey levels crowded about 0.5 like LIC's: the mean of 16 white-noise values (an Irwin-Hall spread).
std::vector<float> crowded_greys(int count) {
    const std::vector<float> noise = gsv::white_noise(16, count, 7);
    std::vector<float> grey(static_cast<std::size_t>(count), 0.0f);
    for (std::size_t i = 0; i < grey.size(); ++i)
        for (std::size_t k = 0; k < 16; ++k) grey[i] += noise[16 * i + k] / 16.0f;
    return grey;
}

// The share of `values` mapped below `level` by `curve`.
double share_below(const ToneCurve& curve, const std::vector<float>& values, float level) {
    long below = 0;
    for (float v : values) below += curve(v) < level;
    return static_cast<double>(below) / static_cast<double>(values.size());
}

}  // namespace

TEST_CASE("lic contrast: off, and an image with one grey level, leave every value as it is", "[unit][lic_contrast]") {
    const std::vector<float> grey = crowded_greys(4096);
    const ToneCurve off = make_tone_curve(grey, LicContrast::Off);
    CHECK(off.identity());
    for (float v : {0.0f, 0.37f, 0.5f, 1.0f}) CHECK(off(v) == v);
    for (LicContrast c : {LicContrast::Stretch, LicContrast::Equalize}) {
        const ToneCurve flat = make_tone_curve(std::vector<float>(100, 0.25f), c);
        CHECK(flat.identity());
        CHECK(flat(0.25f) == 0.25f);
        CHECK(make_tone_curve({}, c).identity());
    }
}

TEST_CASE("lic contrast: a stretch takes the 0.5th and 99.5th percentiles to black and white, linearly between", "[unit][lic_contrast]") {
    std::vector<float> grey;
    for (int i = 0; i <= 1000; ++i) grey.push_back(0.4f + 0.2f * static_cast<float>(i) / 1000.0f);  // 0.4 .. 0.6
    std::reverse(grey.begin(), grey.end());  // any order
    const ToneCurve curve = make_tone_curve(grey, LicContrast::Stretch);
    CHECK(curve.low == Approx(0.401).margin(1e-6));
    CHECK(curve.high == Approx(0.599).margin(1e-6));
    CHECK(curve(0.401f) == Approx(0.0).margin(1e-5));
    CHECK(curve(0.5f) == Approx(0.5).margin(1e-5));
    CHECK(curve(0.599f) == Approx(1.0).margin(1e-5));
    CHECK(curve(0.3f) == 0.0f);  // clipped, not extrapolated
    CHECK(curve(0.7f) == 1.0f);
    // The crowded greys: about 1% of them clipped, half on each side.
    const std::vector<float> crowded = crowded_greys(8000);
    const ToneCurve stretch = make_tone_curve(crowded, LicContrast::Stretch);
    CHECK(share_below(stretch, crowded, 1e-6f) == Approx(0.005).margin(0.002));
    CHECK(1.0 - share_below(stretch, crowded, 1.0f - 1e-6f) == Approx(0.005).margin(0.002));
}

TEST_CASE("lic contrast: equalisation spreads crowded grey levels evenly, in order, and skips NaN and Inf", "[unit][lic_contrast]") {
    std::vector<float> grey = crowded_greys(8000);
    const ToneCurve before = make_tone_curve(grey, LicContrast::Equalize);
    grey.push_back(std::numeric_limits<float>::quiet_NaN());
    grey.push_back(std::numeric_limits<float>::infinity());
    const ToneCurve curve = make_tone_curve(grey, LicContrast::Equalize);
    CHECK(curve.low == before.low);
    CHECK(curve.high == before.high);
    CHECK(curve.values == before.values);
    grey.resize(grey.size() - 2);
    // Every tenth of the output range holds a tenth of the pixels.
    for (int decile = 1; decile < 10; ++decile)
        CHECK(share_below(curve, grey, static_cast<float>(decile) / 10.0f) == Approx(decile / 10.0).margin(0.01));
    CHECK(std::is_sorted(curve.values.begin(), curve.values.end()));
    CHECK(curve.values.front() == 0.0f);
    CHECK(curve.values.back() == 1.0f);
    CHECK(std::isnan(curve(std::numeric_limits<float>::quiet_NaN())));
}

TEST_CASE("lic contrast: names, and a sweep refused with a contrast on", "[unit][lic_contrast]") {
    CHECK(gsv::lic_contrast_from_name("equalize") == LicContrast::Equalize);
    CHECK(std::string(gsv::name_of(gsv::kLicContrastNames, LicContrast::Stretch)) == "stretch");
    CHECK(gsv::test::gsv_error_message([] { gsv::lic_contrast_from_name("gamma"); }) ==
          "unknown contrast 'gamma' (known: off, stretch, equalize)");
    CHECK_NOTHROW(gsv::check_sweepable(LicContrast::Off));
    CHECK(gsv::test::gsv_error_message([] { gsv::check_sweepable(LicContrast::Stretch); }).find("contrast=stretch") == 0);
}
