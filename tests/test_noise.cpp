#include "catch.hpp"

#include "common/core/splitmix64.h"
#include "support/flow/noise.h"
#include "test_support.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using gsv::test::gsv_error_message;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Pearson correlation of each texel with its neighbour (dx, dy) away.
double neighbour_correlation(const std::vector<float>& v, int width, int height, int dx, int dy, double mean,
                             double variance) {
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y + dy < height; ++y)
        for (int x = 0; x + dx < width; ++x) {
            sum += (v[y * width + x] - mean) * (v[(y + dy) * width + x + dx] - mean);
            ++count;
        }
    return sum / count / variance;
}

}  // namespace

TEST_CASE("splitmix64 reproduces the reference generator's outputs", "[unit][noise][flow]") {
    // Vigna's splitmix64.c with state 0: published test vectors, so any platform difference shows here.
    std::uint64_t state = 0;
    CHECK(gsv::splitmix64_next(state) == 0xE220A8397B1DCDAFull);
    CHECK(gsv::splitmix64_next(state) == 0x6E789E6AA1B965F4ull);
    CHECK(gsv::splitmix64_next(state) == 0x06C45D188009454Full);
    // Seed 0 mixes to state 0, so its first draw is the generator's first output.
    CHECK(gsv::hash64(0, 0) == 0xE220A8397B1DCDAFull);
    CHECK(gsv::unit_float(~std::uint64_t(0)) < 1.0f);
    CHECK(gsv::unit_double(~std::uint64_t(0)) < 1.0);
}

TEST_CASE("white noise is pinned to the hash of the texel index, row 0 at the bottom", "[unit][noise][flow]") {
    const std::vector<float> first = gsv::white_noise(1, 1, 0);
    REQUIRE(first.size() == 1);
    CHECK(first[0] == 0xE220A8 / 16777216.0f);  // the top 24 bits of hash64(0, 0)

    const int width = 5, height = 3;
    const std::vector<float> noise = gsv::white_noise(width, height, 42);
    REQUIRE(noise.size() == static_cast<std::size_t>(width * height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            CHECK(noise[y * width + x] == gsv::unit_float(gsv::hash64(42, static_cast<std::uint64_t>(y * width + x))));
}

TEST_CASE("white noise is deterministic and depends on the seed", "[unit][noise][flow]") {
    const std::vector<float> a = gsv::white_noise(64, 32, 7);
    CHECK(a == gsv::white_noise(64, 32, 7));
    const std::vector<float> b = gsv::white_noise(64, 32, 8);
    int same = 0;
    for (std::size_t i = 0; i < a.size(); ++i) same += a[i] == b[i];
    CHECK(same < 5);
}

TEST_CASE("white noise is uniform on the unit interval with independent neighbours", "[unit][noise][flow]") {
    const int side = 256;
    const std::vector<float> noise = gsv::white_noise(side, side, 1);
    double sum = 0.0, sum_sq = 0.0;
    for (float v : noise) {
        REQUIRE(v >= 0.0f);
        REQUIRE(v < 1.0f);
        sum += v;
        sum_sq += double(v) * v;
    }
    const double n = static_cast<double>(noise.size());
    const double mean = sum / n;
    const double variance = sum_sq / n - mean * mean;
    // Standard errors for 65536 uniform samples: 0.0011 on the mean, 0.0003 on the variance.
    CHECK(std::abs(mean - 0.5) < 0.01);
    CHECK(std::abs(variance - 1.0 / 12.0) < 0.003);

    int histogram[16] = {};
    for (float v : noise) ++histogram[static_cast<int>(v * 16)];
    for (int count : histogram) CHECK(std::abs(count - 4096) < 400);  // ~6 standard deviations

    // Structure along rows or columns would show up as streaks in every LIC image.
    CHECK(std::abs(neighbour_correlation(noise, side, side, 1, 0, mean, variance)) < 0.02);
    CHECK(std::abs(neighbour_correlation(noise, side, side, 0, 1, mean, variance)) < 0.02);
}

TEST_CASE("white noise refuses sizes outside 1..8192", "[unit][noise][flow]") {
    CHECK(gsv_error_message([] { gsv::white_noise(0, 4, 1); }) == "white_noise: width must be 1..8192, got 0");
    CHECK(gsv_error_message([] { gsv::white_noise(4, 8193, 1); }) == "white_noise: height must be 1..8192, got 8193");
    CHECK(contains(gsv_error_message([] { gsv::white_noise(-3, 4, 1); }), "got -3"));
    CHECK(gsv::white_noise(8192, 1, 1).size() == 8192);
}
