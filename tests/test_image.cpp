#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "catch.hpp"
#include "common/core/error.h"
#include "common/image/image.h"
#include "common/image/image_compare.h"
#include "test_support.h"

namespace fs = std::filesystem;

namespace {



bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

gsv::Image filled(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) {
    gsv::Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = image.at(x, y);
            p[0] = r, p[1] = g, p[2] = b, p[3] = a;
        }
    return image;
}

// Every pixel and channel different, so a round trip that swapped rows or channels would show.
gsv::Image gradient(int w, int h) {
    gsv::Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = image.at(x, y);
            p[0] = std::uint8_t(x * 7 + y);
            p[1] = std::uint8_t(y * 11 + x * 3);
            p[2] = std::uint8_t(x * y);
            p[3] = std::uint8_t(255 - (x + y) % 128);
        }
    return image;
}

// Gray images (R = G = B, alpha 255) so that the luma ssim_luma computes is exactly the gray
// value scikit-image is given. The formulas use only integer arithmetic so that the Python
// script in the SSIM test reproduces them bit for bit.
using GrayFormula = int (*)(int x, int y);
constexpr int kSsimW = 64, kSsimH = 48;

int ssim_base(int x, int y) { return (x * 5 + y * 3 + ((x / 8 + y / 8) % 2) * 60) % 256; }
int ssim_noisy(int x, int y) {
    const int noise = (x * 1103 + y * 2711 + x * y * 17) % 41 - 20;
    return std::clamp(ssim_base(x, y) + noise, 0, 255);
}
int ssim_blurred(int x, int y) {  // 3x3 box filter, edges clamped, integer division
    int sum = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            sum += ssim_base(std::clamp(x + dx, 0, kSsimW - 1), std::clamp(y + dy, 0, kSsimH - 1));
    return sum / 9;
}
int ssim_contrast(int x, int y) { return ssim_base(x, y) * 3 / 4 + 40; }

gsv::Image gray_image(GrayFormula formula, long* pixel_sum = nullptr) {
    gsv::Image image(kSsimW, kSsimH);
    long sum = 0;
    for (int y = 0; y < kSsimH; ++y)
        for (int x = 0; x < kSsimW; ++x) {
            const int v = formula(x, y);
            sum += v;
            std::uint8_t* p = image.at(x, y);
            p[0] = p[1] = p[2] = std::uint8_t(v);
            p[3] = 255;
        }
    if (pixel_sum) *pixel_sum = sum;
    return image;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Image, PNG files, float conversion

TEST_CASE("image: a new image is transparent black and at() addresses rows from the top", "[unit]") {
    gsv::Image image(3, 2);
    CHECK(image.rgba.size() == 3 * 2 * 4);
    CHECK(!image.empty());
    CHECK(gsv::Image().empty());
    CHECK(gsv::is_blank(image));
    image.at(2, 1)[0] = 9;
    CHECK(image.rgba[(1 * 3 + 2) * 4] == 9);
    CHECK_THROWS_AS(gsv::Image(-1, 4), gsv::Error);
}

TEST_CASE("image: PNG round trip keeps every RGBA byte and creates parent directories", "[unit]") {
    gsv::test::TempDir dir;
    const fs::path file = dir.path() / "nested" / "deeper" / "gradient.png";
    const gsv::Image original = gradient(37, 23);
    gsv::write_png(file, original);
    REQUIRE(fs::exists(file));
    const gsv::Image loaded = gsv::read_png(file);
    CHECK(loaded.width == 37);
    CHECK(loaded.height == 23);
    CHECK(loaded.rgba == original.rgba);
}

TEST_CASE("image: reading a missing PNG is a gsv::Error naming the path", "[unit]") {
    gsv::test::TempDir dir;
    const fs::path missing = dir.path() / "no_such_file.png";
    const std::string message = gsv::test::gsv_error_message([&] { gsv::read_png(missing); });
    CHECK(contains(message, "cannot read PNG '" + missing.string() + "'"));
    CHECK(!contains(message, "\n"));
}

TEST_CASE("image: reading a truncated or corrupt PNG is a gsv::Error naming the path", "[unit]") {
    gsv::test::TempDir dir;
    const fs::path truncated = dir.path() / "truncated.png";
    gsv::write_png(truncated, gradient(64, 64));
    fs::resize_file(truncated, fs::file_size(truncated) / 2);
    std::string message = gsv::test::gsv_error_message([&] { gsv::read_png(truncated); });
    CHECK(contains(message, "cannot read PNG '" + truncated.string() + "': "));

    const fs::path garbage = dir.path() / "garbage.png";
    std::ofstream(garbage) << "this is not a PNG file";
    message = gsv::test::gsv_error_message([&] { gsv::read_png(garbage); });
    CHECK(contains(message, "cannot read PNG '" + garbage.string() + "': "));

    const fs::path empty = dir.path() / "empty.png";
    std::ofstream{empty};
    message = gsv::test::gsv_error_message([&] { gsv::read_png(empty); });
    CHECK(contains(message, "cannot read PNG '" + empty.string() + "': "));
}

TEST_CASE("image: writing where a directory cannot be made is a gsv::Error naming the path", "[unit]") {
    gsv::test::TempDir dir;
    const fs::path blocker = dir.path() / "a_file";
    std::ofstream(blocker) << "x";
    const fs::path target = blocker / "out.png";
    const std::string message = gsv::test::gsv_error_message([&] { gsv::write_png(target, gradient(2, 2)); });
    CHECK(contains(message, "cannot write PNG '" + target.string() + "'"));

    CHECK(contains(gsv::test::gsv_error_message([&] { gsv::write_png(dir.path() / "e.png", gsv::Image()); }),
                   "e.png"));
}

TEST_CASE("image: to_rgba8 clamps, rounds and shows NaN as magenta", "[unit]") {
    gsv::ImageF image(4, 1);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const float values[4][4] = {
        {0.0f, 1.0f, 0.5f, 1.0f},      // 0.5 * 255 = 127.5 rounds up
        {-0.5f, 2.0f, 0.2f, 0.25f},    // 0.2 * 255 = 51, 0.25 * 255 = 63.75
        {0.3f, nan, 0.3f, 1.0f},       // any NaN channel
        {inf, -inf, 0.0f, 1.0f},       // infinities clamp like any other value
    };
    for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 4; ++c) image.at(x, 0)[c] = values[x][c];

    const gsv::Image out = gsv::to_rgba8(image);
    const std::vector<std::uint8_t> expected = {
        0, 255, 128, 255,
        0, 255, 51, 64,
        255, 0, 255, 255,
        255, 0, 0, 255,
    };
    CHECK(out.rgba == expected);
}

// ---------------------------------------------------------------------------------------------
// Comparison

TEST_CASE("image: identical images compare equal", "[unit]") {
    const gsv::Image a = gradient(20, 15);
    const gsv::ImageDiff diff = gsv::compare_images(a, a, {});
    CHECK(!diff.size_mismatch);
    CHECK(diff.max_channel_diff == 0);
    CHECK(diff.differing_pixels == 0);
    CHECK(diff.total_pixels == 300);
    CHECK(diff.rmse == 0);
    CHECK(std::isinf(diff.psnr));
    CHECK(diff.ssim == Approx(1.0).margin(1e-12));
    CHECK(diff.diff_x1 < diff.diff_x0);  // empty box
    CHECK(diff.within({}));
    CHECK(diff.summary() == "max diff 0, 0 of 300 px differ (0.00%), PSNR inf dB, SSIM 1.000");
}

TEST_CASE("image: one changed pixel is counted, boxed and measured", "[unit]") {
    const gsv::Image expected = filled(10, 10, 100, 100, 100, 255);
    gsv::Image actual = expected;
    actual.at(3, 4)[0] = 130;  // R off by 30

    const gsv::ImageDiff diff = gsv::compare_images(actual, expected, {});
    CHECK(diff.max_channel_diff == 30);
    CHECK(diff.differing_pixels == 1);
    CHECK(diff.diff_x0 == 3);
    CHECK(diff.diff_y0 == 4);
    CHECK(diff.diff_x1 == 3);
    CHECK(diff.diff_y1 == 4);
    // RMSE over 100 pixels x 3 channels with one squared error of 900: sqrt(900 / 300).
    CHECK(diff.rmse == Approx(std::sqrt(3.0)));
    CHECK(diff.psnr == Approx(20.0 * std::log10(255.0 / std::sqrt(3.0))));
    CHECK(diff.ssim < 1.0);
    CHECK(!diff.within({}));
    CHECK(diff.within({30, 0.0}));   // a channel exactly at the tolerance does not differ
    CHECK(!diff.within({29, 0.0}));
    CHECK(diff.within({0, 0.01}));   // or one pixel in a hundred may differ
    const std::string summary = diff.summary();
    CHECK(summary.rfind("max diff 30, 1 of 100 px differ (1.00%) in [3,4]-[3,4], PSNR 43.4 dB, SSIM ", 0) == 0);

    // The count follows the tolerance given to compare_images.
    CHECK(gsv::compare_images(actual, expected, {30, 0.0}).differing_pixels == 0);
}

TEST_CASE("image: an alpha-only difference counts as a differing pixel but not in RMSE", "[unit]") {
    const gsv::Image expected = filled(4, 4, 10, 20, 30, 255);
    gsv::Image actual = expected;
    actual.at(0, 0)[3] = 0;
    const gsv::ImageDiff diff = gsv::compare_images(actual, expected, {});
    CHECK(diff.max_channel_diff == 255);
    CHECK(diff.differing_pixels == 1);
    CHECK(diff.rmse == 0);
    CHECK(!diff.within({254, 0.0}));
}

TEST_CASE("image: a size mismatch fails whatever the tolerance", "[unit]") {
    const gsv::ImageDiff diff = gsv::compare_images(gradient(8, 6), gradient(6, 8), {255, 1.0});
    CHECK(diff.size_mismatch);
    CHECK(!diff.within({255, 1.0}));
    CHECK(diff.summary() == "size mismatch: actual 8x6, expected 6x8");
}

TEST_CASE("image: exactly the pixel budget passes and one more fails", "[unit]") {
    const gsv::Image expected = filled(10, 10, 0, 0, 0, 255);
    const auto with_changed_pixels = [&](int count) {
        gsv::Image actual = expected;
        for (int i = 0; i < count; ++i) actual.at(i % 10, i / 10)[1] = 50;
        return gsv::compare_images(actual, expected, {10, 0.29});
    };
    // 0.29 * 100 is 28.999999999999996 in doubles; the budget still means 29 pixels.
    const gsv::ImageDiff at_budget = with_changed_pixels(29);
    CHECK(at_budget.differing_pixels == 29);
    CHECK(at_budget.within({10, 0.29}));
    const gsv::ImageDiff over_budget = with_changed_pixels(30);
    CHECK(over_budget.differing_pixels == 30);
    CHECK(!over_budget.within({10, 0.29}));
    CHECK(over_budget.within({10, 0.30}));
    CHECK(over_budget.within({50, 0.0}));  // judged with a looser tolerance than it was counted with
    CHECK(over_budget.diff_x0 == 0);
    CHECK(over_budget.diff_y0 == 0);
    CHECK(over_budget.diff_x1 == 9);
    CHECK(over_budget.diff_y1 == 2);
}

TEST_CASE("image: the difference map shows every pixel over the tolerance brightly, however small the excess", "[unit]") {
    const gsv::Image expected = filled(5, 1, 90, 90, 90, 255);
    gsv::Image actual = expected;
    actual.at(1, 0)[0] = 92;   // within a tolerance of 2: the expected image, dimmed
    actual.at(2, 0)[1] = 93;   // 1 level over: full red
    actual.at(3, 0)[2] = 160;  // far over: yellow
    actual.at(4, 0)[3] = 0;    // alpha counts too
    const gsv::Image heat = gsv::difference_heatmap(actual, expected, 2);
    const std::vector<std::uint8_t> want = {
        30, 30, 30, 255,
        30, 30, 30, 255,
        255, 0, 0, 255,
        255, 255, 0, 255,
        255, 255, 0, 255,
    };
    CHECK(heat.rgba == want);
    CHECK_THROWS_AS(gsv::difference_heatmap(gradient(2, 2), gradient(3, 2), 0), gsv::Error);
}

// A dark background with bright one-pixel points, as lab 05 draws particles: the neighbourhood comparison
// (ImageTolerance::neighbourhood) forgives where a point lands, never a point missing or of the wrong colour.
namespace {

gsv::Image points(const std::vector<std::pair<int, int>>& at, std::uint8_t r = 250, std::uint8_t g = 200, std::uint8_t b = 40) {
    gsv::Image image = filled(16, 12, 10, 12, 20, 255);
    for (const auto& [x, y] : at) {
        std::uint8_t* p = image.at(x, y);
        p[0] = r, p[1] = g, p[2] = b;
    }
    return image;
}

}  // namespace

TEST_CASE("image: a point moved by one pixel passes within a neighbourhood of 1 and fails without", "[unit]") {
    const gsv::Image golden = points({{5, 5}, {10, 3}, {0, 0}, {15, 11}});
    for (const auto& [dx, dy] : std::vector<std::pair<int, int>>{{1, 0}, {0, 1}, {-1, 1}, {1, 1}}) {
        INFO("moved by " << dx << "," << dy);
        // The corner points move inwards, so every point stays in the picture.
        const gsv::Image moved = points({{5 + dx, 5 + dy}, {10 + dx, 3 + dy}, {std::max(0, dx), std::max(0, dy)},
                                         {std::min(15, 15 + dx), std::min(11, 11 + dy)}});
        const gsv::ImageDiff exact = gsv::compare_images(moved, golden, {2, 0.0});
        CHECK(exact.differing_pixels >= 4);
        CHECK_FALSE(exact.within({2, 0.0}));
        const gsv::ImageDiff near = gsv::compare_images(moved, golden, {2, 0.0, 1});
        CHECK(near.neighbourhood == 1);
        CHECK(near.differing_pixels == 0);
        CHECK(near.max_channel_diff == 0);
        CHECK(near.within({2, 0.0, 1}));
        CHECK(near.summary().find("0 of 192 px differ (0.00%), matched within 1 px") != std::string::npos);
    }
    // Two pixels is not one: a neighbourhood of 1 does not reach, 2 does.
    const gsv::Image far = points({{7, 5}, {12, 3}, {2, 0}, {13, 11}});
    CHECK_FALSE(gsv::compare_images(far, golden, {2, 0.0, 1}).within({2, 0.0, 1}));
    CHECK(gsv::compare_images(far, golden, {2, 0.0, 2}).within({2, 0.0, 2}));
}

TEST_CASE("image: a missing point, an extra point or a point of the wrong colour fails within a neighbourhood", "[unit]") {
    const gsv::Image golden = points({{5, 5}, {10, 3}});
    // Missing: the golden's point finds no match in the actual image, though the actual background matches the
    // golden's background beside it (one direction alone would pass this).
    const gsv::ImageDiff missing = gsv::compare_images(points({{5, 5}}), golden, {2, 0.0, 1});
    CHECK(missing.differing_pixels == 1);
    CHECK(missing.diff_x0 == 10);
    CHECK(missing.diff_y0 == 3);
    CHECK(missing.max_channel_diff == 240);
    CHECK_FALSE(missing.within({2, 0.0, 1}));
    // Extra: the actual point finds no match in the golden.
    CHECK_FALSE(gsv::compare_images(points({{5, 5}, {10, 3}, {1, 8}}), golden, {2, 0.0, 1}).within({2, 0.0, 1}));
    // The wrong colour, in place or moved by a pixel: no neighbour has it.
    for (const int dx : {0, 1}) {
        const gsv::ImageDiff recoloured = gsv::compare_images(points({{5 + dx, 5}, {10 + dx, 3}}, 250, 120, 40), golden, {2, 0.0, 1});
        INFO("moved by " << dx);
        CHECK(recoloured.differing_pixels >= 2);
        CHECK(recoloured.max_channel_diff == 80);
        CHECK_FALSE(recoloured.within({2, 0.0, 1}));
        CHECK(recoloured.within({80, 0.0, 1}));
    }
    // The map shows the missing point, matched the same way.
    const gsv::Image heat = gsv::difference_heatmap(points({{5, 5}}), golden, 2, 1);
    CHECK(heat.at(10, 3)[0] == 255);
    CHECK(heat.at(5, 5)[0] != 255);
}

TEST_CASE("image: a neighbourhood of 0 is the exact comparison, result for result", "[unit]") {
    gsv::Image expected = gradient(23, 17);
    gsv::Image actual = expected;
    for (int i = 0; i < 60; ++i) actual.at((i * 7) % 23, (i * 5) % 17)[i % 4] = static_cast<std::uint8_t>((i * 37) % 256);
    const gsv::ImageDiff plain = gsv::compare_images(actual, expected, {3, 0.05});
    const gsv::ImageDiff zero = gsv::compare_images(actual, expected, {3, 0.05, 0});
    CHECK(zero.neighbourhood == 0);
    CHECK(zero.max_channel_diff == plain.max_channel_diff);
    CHECK(zero.differing_pixels == plain.differing_pixels);
    CHECK(zero.pixels_by_max_diff == plain.pixels_by_max_diff);
    CHECK(zero.summary() == plain.summary());
    CHECK(zero.summary().find("matched") == std::string::npos);
    // The differences are the plain per-pixel maximum.
    const std::vector<std::uint8_t> d = gsv::matched_differences(actual, expected, 0);
    long over = 0;
    for (const auto v : d) over += v > 3;
    CHECK(over == plain.differing_pixels);
    // Judged with another neighbourhood than it was compared with: refused, not silently wrong.
    CHECK_THROWS_AS(plain.within({3, 0.05, 1}), gsv::Error);
    // A neighbourhood never makes a difference larger than the exact one.
    const gsv::ImageDiff one = gsv::compare_images(actual, expected, {3, 0.05, 1});
    CHECK(one.differing_pixels <= plain.differing_pixels);
    CHECK(one.max_channel_diff <= plain.max_channel_diff);
}

TEST_CASE("image: is_blank is true only when every pixel is the same", "[unit]") {
    gsv::Image image = filled(6, 5, 12, 34, 56, 255);
    CHECK(gsv::is_blank(image));
    image.at(5, 4)[3] = 254;
    CHECK(!gsv::is_blank(image));
    CHECK(gsv::is_blank(gsv::Image()));
}

TEST_CASE("image: float_stats counts NaN and Inf and ranges over finite values", "[unit]") {
    gsv::ImageF image(2, 2);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const float values[16] = {0.5f, nan, -2.0f, 1.0f,  inf, 3.25f, nan, 1.0f,
                              0.0f, -inf, 0.1f, 1.0f,  nan, 0.2f, 0.3f, 1.0f};
    std::copy(values, values + 16, image.rgba.begin());
    const gsv::FloatStats stats = gsv::float_stats(image);
    CHECK(stats.nan_count == 3);
    CHECK(stats.inf_count == 2);
    CHECK(stats.min == -2.0f);
    CHECK(stats.max == 3.25f);

    gsv::ImageF all_nan(1, 1);
    std::fill(all_nan.rgba.begin(), all_nan.rgba.end(), nan);
    const gsv::FloatStats none_finite = gsv::float_stats(all_nan);
    CHECK(none_finite.nan_count == 4);
    CHECK(none_finite.min == 0.0f);
    CHECK(none_finite.max == 0.0f);
}

// ---------------------------------------------------------------------------------------------
// SSIM

// Reference values from scikit-image 0.19.3 (Debian 12 package python3-skimage 0.19.3-8), with
// a = base, b = each variant, both 64x48 numpy uint8 arrays built by the same integer formulas
// as ssim_base/ssim_noisy/ssim_blurred/ssim_contrast above:
//   skimage.metrics.structural_similarity(a, b, gaussian_weights=True, sigma=1.5,
//                                         use_sample_covariance=False, data_range=255)
// skimage filters with truncate=3.5 (an 11-tap window) and averages the SSIM map after cropping
// 5 pixels from each side. The pixel sums check that the images here are the ones it was given.
TEST_CASE("image: ssim_luma matches scikit-image on gray images", "[unit]") {
    long sum = 0;
    const gsv::Image base = gray_image(ssim_base, &sum);
    CHECK(sum == 389376);

    const gsv::Image noisy = gray_image(ssim_noisy, &sum);
    CHECK(sum == 388237);
    CHECK(gsv::ssim_luma(base, noisy) == Approx(0.9200647904778085).margin(1e-4));

    const gsv::Image blurred = gray_image(ssim_blurred, &sum);
    CHECK(sum == 389092);
    CHECK(gsv::ssim_luma(base, blurred) == Approx(0.7777742262342994).margin(1e-4));

    const gsv::Image contrast = gray_image(ssim_contrast, &sum);
    CHECK(sum == 413760);
    CHECK(gsv::ssim_luma(base, contrast) == Approx(0.9423473192410659).margin(1e-4));

    // SSIM is symmetric in its arguments.
    CHECK(gsv::ssim_luma(noisy, base) == Approx(gsv::ssim_luma(base, noisy)).margin(1e-12));
}

TEST_CASE("image: ssim_luma of identical images is 1", "[unit]") {
    const gsv::Image base = gray_image(ssim_base);
    CHECK(gsv::ssim_luma(base, base) == Approx(1.0).margin(1e-12));
    const gsv::Image color = gradient(40, 30);
    CHECK(gsv::ssim_luma(color, color) == Approx(1.0).margin(1e-12));
    // Smaller than one 11x11 window: the whole image is one window.
    const gsv::Image tiny = gradient(5, 4);
    CHECK(gsv::ssim_luma(tiny, tiny) == Approx(1.0).margin(1e-12));
    gsv::Image tiny_changed = tiny;
    tiny_changed.at(2, 2)[1] = std::uint8_t(tiny_changed.at(2, 2)[1] + 100);
    CHECK(gsv::ssim_luma(tiny, tiny_changed) < 1.0);
    CHECK(gsv::ssim_luma(gsv::Image(), gsv::Image()) == 1.0);
    CHECK_THROWS_AS(gsv::ssim_luma(gradient(12, 12), gradient(12, 11)), gsv::Error);
}
