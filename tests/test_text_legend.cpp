// Text on CPU images, the legend drawn beside an image, and the comparison composite: the pieces `render --legend`
// and `compare` are made of, on small images.
#include "catch.hpp"
#include "common/core/error.h"
#include "common/image/comparison_image.h"
#include "common/image/image.h"
#include "common/image/legend.h"
#include "common/image/legend_image.h"
#include "common/image/text.h"
#include "common/image/ui_font.h"
#include "test_support.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <string>

namespace {

gsv::Image filled(int w, int h, gsv::Rgba8 color) {
    gsv::Image image(w, h);
    gsv::fill_rect(image, 0, 0, w, h, color);
    return image;
}

// The box of pixels that differ from the background, inclusive: {x0, y0, x1, y1}; x1 < x0 when there are none.
std::array<int, 4> ink_box(const gsv::Image& image, const gsv::Rgba8& background, int* count = nullptr, int* partial = nullptr) {
    std::array<int, 4> box{image.width, image.height, -1, -1};
    int inked = 0, between = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.at(x, y);
            if (p[0] == background[0] && p[1] == background[1] && p[2] == background[2]) continue;
            ++inked;
            if (p[0] > background[0] && p[0] < 255) ++between;
            box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y)};
        }
    if (count) *count = inked;
    if (partial) *partial = between;
    return box;
}

std::array<int, 3> rgb(const gsv::Image& image, int x, int y) {
    const std::uint8_t* p = image.at(x, y);
    return {p[0], p[1], p[2]};
}

}  // namespace

TEST_CASE("text: a line rasterises anti-aliased ink inside its measured box, wider for longer text and taller for a larger size", "[unit]") {
    const gsv::Rgba8 black{0, 0, 0, 255}, white{255, 255, 255, 255};
    gsv::Image short_line = filled(400, 60, black), long_line = filled(400, 60, black), large = filled(400, 60, black);
    const int end = gsv::draw_text(short_line, 10, 5, "height (m)", 16, white);
    gsv::draw_text(long_line, 10, 5, "height (m) over the land", 16, white);
    gsv::draw_text(large, 10, 5, "height (m)", 32, white);

    int inked = 0, partial = 0;
    const auto box = ink_box(short_line, black, &inked, &partial);
    const gsv::TextSize size = gsv::measure_text("height (m)", 16);
    INFO("ink box " << box[0] << "," << box[1] << " - " << box[2] << "," << box[3] << "; measured " << size.width << "x" << size.height);
    CHECK(inked > 100);
    CHECK(partial > 20);  // anti-aliased edges, not a 1-bit mask
    CHECK(box[0] >= 10);
    CHECK(box[2] < 10 + size.width + 2);
    CHECK(box[1] >= 5);
    CHECK(box[3] < 5 + size.height + 1);
    CHECK(end == 10 + size.width);
    CHECK(size.height >= 16);
    CHECK(size.height <= 18);

    const auto long_box = ink_box(long_line, black);
    const auto large_box = ink_box(large, black);
    CHECK(long_box[2] - long_box[0] > box[2] - box[0] + 50);
    CHECK(gsv::measure_text("height (m) over the land", 16).width > size.width);
    CHECK(large_box[3] - large_box[1] > (box[3] - box[1]) * 3 / 2);
    CHECK(large_box[2] - large_box[0] > (box[2] - box[0]) * 3 / 2);
}

TEST_CASE("text: drawn in colour over the image, clipped at its edges, and an empty line draws nothing", "[unit]") {
    const gsv::Rgba8 grey{40, 40, 40, 255}, red{255, 0, 0, 255};
    gsv::Image image = filled(60, 20, grey);
    gsv::draw_text(image, 30, 2, "clipped at the edge", 14, red);
    int inked = 0;
    const auto box = ink_box(image, grey, &inked);
    CHECK(inked > 0);
    CHECK(box[0] >= 30);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            CHECK(image.at(x, y)[1] <= 40);  // red over grey: green and blue never rise, red never falls
            CHECK(image.at(x, y)[0] >= 40);
        }
    gsv::Image blank = filled(40, 20, grey);
    CHECK(gsv::draw_text(blank, 3, 3, "", 14, red) == 3);
    CHECK(ink_box(blank, grey)[2] < 0);
    CHECK(gsv::test::gsv_error_message([&] { gsv::measure_text("x", 0); }).find("pixel height 0") != std::string::npos);
}

TEST_CASE("text: the font is found, GSV_FONT first, DejaVu Sans before the system fonts of macOS and Windows", "[unit]") {
    const auto candidates = gsv::ui_font_candidates();
    REQUIRE(candidates.size() > 4);
    CHECK(candidates.front().filename() == "DejaVuSans.ttf");
    CHECK(candidates.back().filename().string().find(".ttf") != std::string::npos);
    CHECK(std::filesystem::is_regular_file(gsv::find_ui_font()));
}

TEST_CASE("legend: nice ticks lie in the range 1, 2 or 5 times a power of ten apart, and their text has the decimals they need", "[unit]") {
    CHECK(gsv::nice_ticks(0, 10) == std::vector<double>{0, 2, 4, 6, 8, 10});
    const auto ticks = gsv::nice_ticks(-37.5, 812.25);
    REQUIRE(ticks.size() >= 3);
    CHECK(ticks.size() <= 6);
    CHECK(ticks.front() >= -37.5);
    CHECK(ticks.back() <= 812.25);
    CHECK(gsv::tick_spacing(ticks) == Approx(200));
    const auto small = gsv::nice_ticks(0, 0.3);
    CHECK(small.back() == Approx(0.3));
    CHECK(gsv::tick_text(0.25, 0.25) == "0.25");
    CHECK(gsv::tick_text(0.5, 0.25) == "0.50");
    CHECK(gsv::tick_text(1500, 500) == "1500");
    CHECK(gsv::tick_text(7.5, 2.5) == "7.5");
    CHECK(gsv::tick_text(-1e-12, 0.1) == "0.0");
    CHECK(gsv::nice_ticks(1, 1).empty());
}

TEST_CASE("legend: colours are linear between stops and the end colour beyond them, and a bad legend is refused naming what is wrong", "[unit]") {
    gsv::Legend legend;
    legend.title = "speed";
    legend.min = 0;
    legend.max = 10;
    legend.ramp = {{0, {1, 0, 0, 1}}, {5, {0, 1, 0, 1}}, {10, {0, 0, 1, 0.5f}}};
    CHECK(legend.color_at(2.5)[0] == Approx(0.5));
    CHECK(legend.color_at(2.5)[1] == Approx(0.5));
    CHECK(legend.color_at(7.5)[3] == Approx(0.75));
    CHECK(legend.color_at(-4)[0] == 1);
    CHECK(legend.color_at(40)[2] == 1);
    CHECK_NOTHROW(gsv::check_legend(legend));

    gsv::Legend backwards = legend;
    std::swap(backwards.ramp[1], backwards.ramp[2]);
    CHECK(gsv::test::gsv_error_message([&] { gsv::check_legend(backwards); }).find("stop 2 at 5 is not above") != std::string::npos);
    gsv::Legend empty = legend;
    empty.max = 0;
    CHECK(gsv::test::gsv_error_message([&] { gsv::check_legend(empty); }).find("range [0, 0] is empty") != std::string::npos);
    gsv::Legend bright = legend;
    bright.specials.push_back({"no data", {1.5f, 0, 0, 1}});
    CHECK(gsv::test::gsv_error_message([&] { gsv::check_legend(bright); }).find("'no data' has a channel 1.5") != std::string::npos);
}

TEST_CASE("legend image: the picture is kept, the bar has the ramp's colours from the largest value at the top, swatches their colours", "[unit]") {
    const gsv::Rgba8 ground{10, 20, 30, 255};
    const gsv::Image picture = filled(120, 240, ground);
    gsv::Legend legend;
    legend.title = "height";
    legend.unit = "m";
    legend.min = -100;
    legend.max = 300;
    legend.ramp = {{-100, {1, 0, 0, 1}}, {100, {0, 1, 0, 1}}, {300, {0, 0, 1, 1}}};
    legend.ticks = gsv::nice_ticks(legend.min, legend.max);
    legend.specials = {{"no data", {0.5f, 0.5f, 0.5f, 1}}, {"above the range", {1, 1, 0, 1}}};
    legend.note = "Unlit colours.";
    gsv::LegendPlacement where;
    const gsv::Image out = gsv::with_legend(picture, legend, &where);

    REQUIRE(out.width > picture.width + 40);
    REQUIRE(out.height == picture.height);
    for (int y = 0; y < picture.height; y += 7)
        for (int x = 0; x < picture.width; x += 5) CHECK(rgb(out, x, y) == std::array<int, 3>{10, 20, 30});

    const int x0 = where.bar[0], x1 = where.bar[2], y0 = where.bar[1], y1 = where.bar[3];
    REQUIRE(x0 >= picture.width);
    REQUIRE(x1 > x0 + 5);
    REQUIRE(y1 - y0 > picture.height / 3);
    const int mid_x = (x0 + x1) / 2;
    // Top: 300 is blue; bottom: -100 red; half way, 100, green.
    const auto top = rgb(out, mid_x, y0), bottom = rgb(out, mid_x, y1 - 1), middle = rgb(out, mid_x, (y0 + y1) / 2);
    CHECK(top[2] > 245);
    CHECK(top[0] == 0);
    CHECK(bottom[0] > 245);
    CHECK(bottom[2] == 0);
    CHECK(middle[1] > 245);
    // Every row between: red falls and blue rises going up, never back.
    for (int y = y1 - 2; y >= y0; --y) {
        CHECK(rgb(out, mid_x, y)[0] <= rgb(out, mid_x, y + 1)[0]);
        CHECK(rgb(out, mid_x, y)[2] >= rgb(out, mid_x, y + 1)[2]);
    }
    // The whole width of a row is one colour.
    CHECK(rgb(out, x0, (y0 + y1) / 3) == rgb(out, x1 - 1, (y0 + y1) / 3));
    // A row's value: the bar's rows span [min, max].
    CHECK(where.value_at_row(legend, y0) == Approx(300).margin(400.0 / (y1 - y0)));
    CHECK(where.value_at_row(legend, y1 - 1) == Approx(-100).margin(400.0 / (y1 - y0)));

    REQUIRE(where.swatches.size() == 2);
    const auto& grey = where.swatches[0];
    const auto& yellow = where.swatches[1];
    CHECK(rgb(out, (grey[0] + grey[2]) / 2, (grey[1] + grey[3]) / 2) == std::array<int, 3>{128, 128, 128});
    CHECK(rgb(out, (yellow[0] + yellow[2]) / 2, (yellow[1] + yellow[3]) / 2) == std::array<int, 3>{255, 255, 0});
    CHECK(grey[1] >= y1);       // below the bar
    CHECK(yellow[1] >= grey[3]);  // in the legend's order
    // Text beside the bar: the ticks' labels make ink right of it.
    int inked = 0;
    gsv::Image labels(out.width - x1 - 2, y1 - y0);
    for (int y = 0; y < labels.height; ++y)
        for (int x = 0; x < labels.width; ++x) std::copy(out.at(x1 + 2 + x, y0 + y), out.at(x1 + 2 + x, y0 + y) + 4, labels.at(x, y));
    ink_box(labels, {28, 28, 32, 255}, &inked);
    CHECK(inked > 50);
}

TEST_CASE("legend image: a transfer function's opacity is a curve beside the bar, full where opaque and empty where clear", "[unit]") {
    gsv::Legend legend;
    legend.title = "intensity";
    legend.opacity = true;
    legend.ramp = {{0, {1, 1, 1, 0}}, {0.4, {1, 1, 1, 0}}, {0.5, {1, 0.5f, 0, 0}}, {1, {1, 0.5f, 0, 1}}};
    gsv::LegendPlacement where;
    const gsv::Image out = gsv::with_legend(filled(64, 200, {0, 0, 0, 255}), legend, &where);
    const auto& plot = where.opacity_plot;
    REQUIRE(plot[2] > plot[0] + 10);
    CHECK(plot[0] >= where.bar[2]);
    const int w = plot[2] - plot[0];
    // Near the top (opacity near 1) the colour reaches across; in the lower half (opacity 0) only the ground shows.
    CHECK(rgb(out, plot[0] + w * 3 / 4, plot[1]) == std::array<int, 3>{255, 128, 0});
    CHECK(rgb(out, plot[0] + w / 2, (plot[1] + plot[3]) * 3 / 4) == std::array<int, 3>{46, 46, 52});
    // The bar itself shows the colour at full strength, whatever the opacity.
    CHECK(rgb(out, where.bar[0] + 2, where.bar[3] - 1) == std::array<int, 3>{255, 255, 255});
}

TEST_CASE("comparison: the difference is amplified by a power of two, with the panels side by side and the numbers right", "[unit]") {
    gsv::Image yours = filled(40, 30, {100, 100, 100, 255});
    const gsv::Image reference = yours;
    for (int y = 10; y < 20; ++y)
        for (int x = 5; x < 15; ++x) yours.at(x, y)[1] = 110;  // 10 levels of green over 100 pixels
    const gsv::ImageDifference d = gsv::image_difference(yours, reference);
    CHECK(d.max_rgb == 10);
    CHECK(d.differing_pixels == 100);
    CHECK(d.rmse == Approx(std::sqrt(100.0 * 100 / (3.0 * 1200))));
    CHECK(gsv::difference_factor(10) == 16);
    CHECK(gsv::difference_factor(0) == 1);
    CHECK(gsv::difference_factor(1) == 64);
    CHECK(gsv::difference_factor(200) == 1);

    gsv::ComparisonLayout layout;
    const gsv::Image out = gsv::compose_comparison(yours, reference, "yours", "reference", &layout);
    const auto& a = layout.panels[0];
    const auto& b = layout.panels[1];
    const auto& c = layout.panels[2];
    CHECK(a[2] - a[0] == 40);
    CHECK(b[0] >= a[2]);
    CHECK(c[0] >= b[2]);
    CHECK(rgb(out, a[0] + 7, a[1] + 12) == std::array<int, 3>{100, 110, 100});
    CHECK(rgb(out, b[0] + 7, b[1] + 12) == std::array<int, 3>{100, 100, 100});
    CHECK(rgb(out, c[0] + 7, c[1] + 12) == std::array<int, 3>{0, 160, 0});
    CHECK(rgb(out, c[0] + 30, c[1] + 25) == std::array<int, 3>{0, 0, 0});
    CHECK(a[1] > layout.font_px);  // a label above
    CHECK(gsv::test::gsv_error_message([&] { gsv::image_difference(yours, filled(41, 30, {0, 0, 0, 255})); })
              .find("40x30 image with a 41x30") != std::string::npos);
}
