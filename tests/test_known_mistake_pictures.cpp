// The known mistakes a student's copy ships (common/app/known_mistake_pictures.h): pictures reduced to signatures
// (common/image/picture_signature.h) that still tell a mistake from the golden and from another, a file that reads
// back as written and names what is wrong with it, and shipped files made from the kit's lists as they are now.
#include "catch.hpp"
#include "lab_runner.h"
#include "common/app/kit_layout.h"
#include "common/app/known_mistake_pictures.h"
#include "common/core/error.h"
#include "grader/src/diagnose/known_mistakes.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>

using namespace gsv;

namespace {

std::filesystem::path kit_root() { return GSV_SOURCE_ROOT; }

Image flat(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = image.at(x, y);
            p[0] = r, p[1] = g, p[2] = b, p[3] = 255;
        }
    return image;
}

// Streaks of grey along x (horizontal) or along y: the same mean, another direction, as a line integral convolution
// of a field turned by 90 degrees.
Image streaks(int w, int h, bool along_x) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int across = along_x ? y : x;
            const std::uint8_t v = static_cast<std::uint8_t>(128 + 100 * std::sin(across * 1.7));
            std::uint8_t* p = image.at(x, y);
            p[0] = p[1] = p[2] = v, p[3] = 255;
        }
    return image;
}

}  // namespace

TEST_CASE("picture signature: block means and texture, at most 32 blocks along the longer side", "[unit]") {
    CHECK(signature_block(256, 256) == 8);
    CHECK(signature_block(192, 192) == 6);
    CHECK(signature_block(256, 128) == 8);
    CHECK(signature_block(16, 8) == 1);
    const PictureSignature s = picture_signature(flat(256, 192, 200, 100, 50), signature_block(256, 192));
    CHECK(s.colour.width == 32);
    CHECK(s.colour.height == 24);
    CHECK(s.colour.at(5, 7)[0] == 200);
    CHECK(s.colour.at(5, 7)[2] == 50);
    CHECK(s.texture.at(5, 7)[0] == 0);  // flat: no change across x or y
    CHECK(test::gsv_error_message([] { picture_signature(Image(), 4); }).find("empty") != std::string::npos);
    CHECK(test::gsv_error_message([] { picture_signature(flat(8, 8, 0, 0, 0), 0); }).find("positive block") != std::string::npos);
}

TEST_CASE("picture signature: streaks along x and along y have one mean colour and are told apart", "[unit]") {
    const PictureSignature along_x = picture_signature(streaks(256, 256, true), 8);
    const PictureSignature along_y = picture_signature(streaks(256, 256, false), 8);
    const PictureSignature grey = picture_signature(flat(256, 256, 128, 128, 128), 8);
    CHECK(std::abs(int(along_x.colour.at(10, 10)[0]) - int(along_y.colour.at(10, 10)[0])) <= 2);
    CHECK(signature_distance(along_x, along_y) > 10);
    // A student's picture that is the mistake's matches it; the golden's does not; nor does a third picture.
    CHECK(signature_matches(along_y, along_y, along_x));
    CHECK_FALSE(signature_matches(along_x, along_y, along_x));
    CHECK_FALSE(signature_matches(grey, along_y, along_x));
    // A mistake whose signature is the golden's matches nothing: there is nothing to tell it by.
    CHECK_FALSE(signature_matches(along_x, along_x, along_x));
    CHECK(test::gsv_error_message([&] { signature_distance(along_x, picture_signature(flat(64, 64, 0, 0, 0), 8)); })
              .find("different sizes") != std::string::npos);
    const Image shown = signature_picture(grey, 256, 256);
    CHECK(shown.width == 256);
    CHECK(shown.at(100, 100)[1] == 128);
}

TEST_CASE("picture signature: two mistakes composed, their changes added or the colour's ratios multiplied", "[unit]") {
    const PictureSignature golden = picture_signature(flat(64, 64, 100, 100, 100), 8);
    const PictureSignature brighter = picture_signature(flat(64, 64, 150, 100, 100), 8);
    const PictureSignature greener = picture_signature(flat(64, 64, 100, 160, 100), 8);
    const PictureSignature half = picture_signature(flat(64, 64, 50, 50, 50), 8);
    const PictureSignature added = composed_signature(brighter, greener, golden, Composition::Added);
    CHECK(added.colour.at(3, 3)[0] == 150);
    CHECK(added.colour.at(3, 3)[1] == 160);
    CHECK(added.colour.at(3, 3)[2] == 100);
    // A band's colour (brighter red) under shading halved: the product, not the sum of the changes.
    const PictureSignature multiplied = composed_signature(brighter, half, golden, Composition::Multiplied);
    CHECK(multiplied.colour.at(3, 3)[0] == 75);
    CHECK(multiplied.colour.at(3, 3)[1] == 50);
    CHECK(composed_signature(half, half, golden, Composition::Added).colour.at(0, 0)[0] == 0);  // clamped, not wrapped
    CHECK(test::gsv_error_message([&] { composed_signature(brighter, picture_signature(flat(32, 32, 0, 0, 0), 8), golden, Composition::Added); })
              .find("different sizes") != std::string::npos);
}

TEST_CASE("known mistake pictures: written and read back the same, one picture kept once, a bad file named", "[unit]") {
    test::TempDir dir;
    KnownMistakePictures k;
    k.lab = "lab02";
    k.lab_dir = "lab02_lic";
    k.block = 8;
    k.inputs = "0123";
    k.mistakes.push_back({"L02-T1 a", "L02-T1", "the field is turned", "TODO table", false, {}, {"long", "short"}});
    k.mistakes.push_back({"L02-T2 not started", "L02-T2", "not started", "TODO table", true,
                          {{"lic.frag", {{"return vec4(0.0);", "}"}}}}, {"long"}});
    const PictureSignature y = picture_signature(streaks(64, 64, false), 8), g = picture_signature(flat(64, 64, 9, 9, 9), 8);
    k.cases["long"] = {{0, y}, {1, g}};
    k.cases["short"] = {{0, y}};
    std::filesystem::create_directories(KitLayout{dir.path()}.golden_dir("lab02"));
    write_known_mistake_pictures(dir.path(), k);
    const KnownMistakePictures back = read_known_mistake_pictures(dir.path(), "lab02");
    CHECK(back.lab_dir == "lab02_lic");
    CHECK(back.inputs == "0123");
    REQUIRE(back.mistakes.size() == 2);
    CHECK(back.mistakes[0].fails == std::set<std::string>{"long", "short"});
    CHECK(back.mistakes[1].not_started);
    CHECK(back.mistakes[1].starter == k.mistakes[1].starter);
    REQUIRE(back.cases.at("long").size() == 2);
    CHECK(back.cases.at("long")[1].mistake == 1);
    CHECK(back.cases.at("long")[0].signature.colour.rgba == y.colour.rgba);
    CHECK(back.cases.at("short")[0].signature.texture.rgba == y.texture.rgba);
    CHECK(read_png(KitLayout{dir.path()}.golden_dir("lab02") / "mistakes.png").height == 2 * 8);  // two distinct signatures
    // A student's streaks that are the mistake's are matched; the golden's are not.
    CHECK(matching_mistakes(back, "long", streaks(64, 64, false), flat(64, 64, 9, 9, 9)) == std::vector<std::size_t>{0});
    CHECK(matching_mistakes(back, "long", flat(64, 64, 9, 9, 9), flat(64, 64, 9, 9, 9)).empty());
    CHECK(matching_mistakes(back, "no-such-case", streaks(64, 64, false), flat(64, 64, 9, 9, 9)).empty());
    // None shipped: no mistakes, no error.
    CHECK(read_known_mistake_pictures(dir.path(), "lab03").empty());
    const std::filesystem::path file = known_mistakes_file(dir.path(), "lab02");
    // An index beside another atlas than the one it was written with (rows renumbered for a regenerated atlas while
    // the old one was kept: each picture then names another) is refused, naming the index.
    const std::filesystem::path atlas_file = KitLayout{dir.path()}.golden_dir("lab02") / "mistakes.png";
    const Image atlas = read_png(atlas_file);
    Image swapped(atlas.width, atlas.height);
    for (int y = 0; y < atlas.height; ++y)
        std::copy_n(atlas.at(0, (y + atlas.height / 2) % atlas.height), static_cast<std::size_t>(atlas.width) * 4, swapped.at(0, y));
    write_png(atlas_file, swapped);
    const std::string refused = test::gsv_error_message([&] { read_known_mistake_pictures(dir.path(), "lab02"); });
    CHECK(refused.find(file.string()) != std::string::npos);
    CHECK(refused.find("indexes another mistakes.png") != std::string::npos);
    write_png(atlas_file, atlas);
    CHECK(read_known_mistake_pictures(dir.path(), "lab02").cases.at("long").size() == 2);
    // A file that points outside its pictures, or holds another lab's, is named.
    test::replace_in_file(file, "\"row\": 1", "\"row\": 7");
    CHECK(test::gsv_error_message([&] { read_known_mistake_pictures(dir.path(), "lab02"); }).find(file.string()) != std::string::npos);
    test::replace_in_file(file, "\"lab\": \"lab02\"", "\"lab\": \"lab01\"");
    CHECK(test::gsv_error_message([&] { read_known_mistake_pictures(dir.path(), "lab02"); }).find("not lab02") != std::string::npos);
}

TEST_CASE("known mistake pictures: each lab ships its mistakes' pictures, made from its lists, cases, goldens and solution as they are", "[unit]") {
    for (const std::string& lab : test::all_labs()) {
        const KnownMistakes known = known_mistakes(kit_root(), lab);
        const KnownMistakePictures shipped = read_known_mistake_pictures(kit_root(), lab);
        INFO(lab << ": grader/golden/" << lab << "/mistakes.json is stale or missing; after the goldens, run "
                    "build/bin/gsv-grade --update-mistakes --labs " << lab);
        REQUIRE_FALSE(shipped.empty());
        CHECK(shipped.inputs == mistake_pictures_inputs(kit_root(), lab, known.lab_dir));
        REQUIRE(shipped.mistakes.size() == known.mistakes.size());
        for (std::size_t m = 0; m < known.mistakes.size(); ++m) {
            CHECK(shipped.mistakes[m].todo == known.mistakes[m].todo);
            CHECK(shipped.mistakes[m].says == known.mistakes[m].says);
            CHECK(shipped.mistakes[m].not_started == known.mistakes[m].not_started);
            // Never the kit's name of a mistake (it can say what the edit was): the TODO and a letter.
            CHECK(shipped.mistakes[m].id.rfind(known.mistakes[m].todo + " ", 0) == 0);
        }
    }
}
