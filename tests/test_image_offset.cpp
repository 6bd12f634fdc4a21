// The whole picture's offset against the reference (common/image/image_offset.h): a picture moved by a pixel or two
// is found and named, a picture in its place (or one with no structure to line up) is not.
#include "catch.hpp"
#include "common/image/image.h"
#include "common/image/image_offset.h"
#include "gl_fixture.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace {

// `image` moved by (dx, dy) whole pixels, x right and y down; what comes in at the edge is the edge's colour.
gsv::Image moved(const gsv::Image& image, int dx, int dy) {
    gsv::Image out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const int sx = std::clamp(x - dx, 0, image.width - 1), sy = std::clamp(y - dy, 0, image.height - 1);
            std::copy(image.at(sx, sy), image.at(sx, sy) + 4, out.at(x, y));
        }
    return out;
}

gsv::Image golden(const std::string& lab, const std::string& name) {
    return gsv::read_png(gsv::test::source_root() / "grader" / "golden" / lab / (name + ".png"));
}

}  // namespace

TEST_CASE("image offset: a picture moved by whole pixels is found where it went, in both senses", "[unit]") {
    for (const auto& [lab, name] : {std::pair<std::string, std::string>{"lab05", "abc"}, {"lab05", "fountain"}, {"lab01", "phong"},
                                    {"lab01", "gooch"}, {"lab02", "rotation"}, {"lab06", "dvr"}}) {
        const gsv::Image reference = golden(lab, name);
        for (const auto& [dx, dy] : {std::pair<int, int>{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {2, -2}, {1, 1}, {-3, 2}}) {
            INFO(lab << "/" << name << " moved by (" << dx << ", " << dy << ")");
            const gsv::ImageOffset offset = gsv::global_offset(moved(reference, dx, dy), reference);
            REQUIRE(offset.measured);
            CHECK(std::abs(offset.dx - dx) < 0.3);
            CHECK(std::abs(offset.dy - dy) < 0.3);
            CHECK(offset.shifted());
        }
        INFO(lab << "/" << name << " in its place");
        const gsv::ImageOffset still = gsv::global_offset(reference, reference);
        CHECK(still.measured);
        CHECK(still.dx == 0);
        CHECK(still.dy == 0);
        CHECK_FALSE(still.shifted());
    }
}

TEST_CASE("image offset: the words say how far and which way", "[unit]") {
    const gsv::Image reference = golden("lab05", "abc");
    const gsv::ImageOffset offset = gsv::global_offset(moved(reference, 2, -2), reference);
    INFO(offset.text());
    CHECK(offset.text().rfind("the whole picture is shifted by (2, -2) px (2 right, 2 up)", 0) == 0);
}

TEST_CASE("image offset: a flat picture, stripes and a picture of another size are never called shifted", "[unit]") {
    gsv::Image flat(64, 64);
    for (std::size_t i = 0; i < flat.rgba.size(); ++i) flat.rgba[i] = 90;
    gsv::Image other = flat;
    for (std::size_t i = 0; i < other.rgba.size(); i += 4) other.rgba[i] = 120;  // another colour, in its place
    CHECK_FALSE(gsv::global_offset(other, flat).shifted());
    // Vertical stripes two pixels wide repeat every four: moved by four they are the same picture, so only a real
    // improvement over the unshifted match may move the answer.
    gsv::Image stripes(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            std::uint8_t* p = stripes.at(x, y);
            p[0] = p[1] = p[2] = (x / 2) % 2 ? 255 : 0;
            p[3] = 255;
        }
    CHECK_FALSE(gsv::global_offset(stripes, stripes).shifted());
    CHECK_FALSE(gsv::global_offset(gsv::Image(32, 32), gsv::Image(33, 32)).measured);
    CHECK_FALSE(gsv::global_offset(gsv::Image(8, 8), gsv::Image(8, 8)).measured);
}
