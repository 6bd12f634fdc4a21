// LIC's optional contrast (support/flow/lic_contrast.h) as labs 02 and 03 draw it: off, the LIC itself; a stretch
// and equalisation spread the grey levels a projector shows; a sweep with a contrast on is refused.
#include "common/image/image.h"
#include "lab_runner.h"
#include "test_support.h"

#include "catch.hpp"

#include <algorithm>
#include <string>
#include <vector>

using namespace gsv;

namespace {

// The grey levels (red channel) of a PNG, sorted.
std::vector<int> sorted_greys(const std::filesystem::path& png) {
    const Image image = read_png(png);
    std::vector<int> grey;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) grey.push_back(image.rgba[i]);
    std::sort(grey.begin(), grey.end());
    return grey;
}

// The levels between which the middle 98% of the pixels lie.
int spread(const std::vector<int>& sorted) {
    return sorted[sorted.size() * 99 / 100] - sorted[sorted.size() / 100];
}

// The share of pixels at or below `level`.
double share_at_most(const std::vector<int>& sorted, int level) {
    return static_cast<double>(std::upper_bound(sorted.begin(), sorted.end(), level) - sorted.begin()) /
           static_cast<double>(sorted.size());
}

void check_contrast(const std::string& lab, const std::vector<std::string>& settings) {
    test::TempDir dir;
    auto with = [&](const std::string& contrast) {
        std::vector<std::string> s = settings;
        s.push_back("contrast=" + contrast);
        const auto run = test::render(lab, s, dir.path(), contrast);
        INFO(run.process.output);
        REQUIRE(run.exit_code() == 0);
        return sorted_greys(run.png);
    };
    const std::vector<int> off = with("off"), stretch = with("stretch"), equalize = with("equalize");
    INFO(lab << ": middle 98% of the grey levels spread over " << spread(off) << " levels off, " << spread(stretch)
             << " stretched, " << spread(equalize) << " equalised");
    CHECK(spread(off) < 100);
    CHECK(spread(stretch) > 200);
    CHECK(spread(equalize) > 200);
    // A stretch clips 0.5% at each end; equalisation leaves a quarter of the pixels in each quarter of the levels.
    CHECK(share_at_most(stretch, 0) == Approx(0.005).margin(0.004));
    CHECK(1.0 - share_at_most(stretch, 254) == Approx(0.005).margin(0.004));
    for (int quarter = 1; quarter < 4; ++quarter) CHECK(share_at_most(equalize, 64 * quarter - 1) == Approx(0.25 * quarter).margin(0.02));
}

}  // namespace

TEST_CASE("lab02: contrast=stretch and contrast=equalize spread the vortex street's grey levels", "[lab][lab02]") {
    check_contrast("lab02_solution", {"field=file", "time=5", "length=30"});
}

TEST_CASE("lab03: contrast=stretch and contrast=equalize spread the vortex street's grey levels", "[lab][lab03]") {
    check_contrast("lab03_solution", {"field=file", "time=2", "length=30"});
}

TEST_CASE("lab02 and lab03: a sweep with a contrast on is refused in one line", "[lab][lab02][lab03]") {
    test::TempDir dir;
    for (const std::string lab : {"lab02_solution", "lab03_solution"}) {
        const auto run = test::run_lab(lab, {"sweep", "--size", "64x64", "--set", "contrast=equalize", "--out-dir", dir.path().string()},
                                       dir.path());
        INFO(run.process.output);
        CHECK(run.exit_code() == 1);
        CHECK(run.process.output.find("contrast=equalize draws each image through a tone curve of its own") != std::string::npos);
    }
}
