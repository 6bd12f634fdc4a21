// Render mode writes the arrays a lab hands in beside its image, raw little-endian float32, and lists them in
// its JSON report; a lab that hands in none writes what it always did.
#include "catch.hpp"
#include "test_support.h"

#include "common/app/app.h"
#include "common/gl/gl.h"
#include "common/io/json.h"
#include "common/io/little_endian.h"

#include <memory>
#include <string>
#include <vector>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

class ArraysLab : public Lab {
public:
    explicit ArraysLab(std::vector<DataArray> arrays) : arrays_(std::move(arrays)) {}
    LabInfo info() const override { return {"arrays", "render mode arrays test lab"}; }
    void declare(Params& params) override { params.add_float("shade", 0.5, 0, 1, "grey"); }
    void setup(LabKit&) override {}
    void render(LabKit& kit, const Frame&) override {
        const float v = kit.params().get_float("shade");
        glClearColor(v, v, v, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        ++frames_;
    }
    std::vector<DataArray> readback(LabKit&) override {
        // After the last timed frame: the numbers match what the image shows.
        for (auto& a : arrays_)
            if (!a.values.empty()) a.values[0] = float(frames_);
        return arrays_;
    }

private:
    std::vector<DataArray> arrays_;
    int frames_ = 0;
};

int render(const std::vector<DataArray>& arrays, const fs::path& png) {
    const std::vector<std::string> args{"arrays", "render", "--size", "8x8", "--out", png.string(), "--frames", "2",
                                        "--warmup", "1", "--arrays"};
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    return run_lab([&] { return std::unique_ptr<Lab>(std::make_unique<ArraysLab>(arrays)); }, "tests/shaders", "solution", static_cast<int>(argv.size()),
                   argv.data());
}

std::vector<float> floats_in(const fs::path& file) {
    const std::string bytes = test::read_text(file);
    std::vector<float> values;
    for (std::size_t i = 0; i + 4 <= bytes.size(); i += 4)
        values.push_back(float_from_le_bytes(reinterpret_cast<const unsigned char*>(bytes.data() + i)));
    return values;
}

}  // namespace

TEST_CASE("render: the arrays a lab hands in are written beside the image and listed in its report", "[lab]") {
    test::TempDir dir;
    const fs::path png = dir.path("case.png");
    const std::vector<DataArray> arrays{{"positions", 4, {0, 1, 2, 3, 4, 5, 6, 7}}, {"ids", 1, {9, 8, 7}}};
    REQUIRE(render(arrays, png) == 0);
    CHECK(fs::exists(png));
    CHECK(floats_in(dir.path("case.positions.f32")) == std::vector<float>{3, 1, 2, 3, 4, 5, 6, 7});  // 1 + 2 frames
    CHECK(floats_in(dir.path("case.ids.f32")) == std::vector<float>{3, 8, 7});

    const Json report = read_json_file(dir.path("case.json"));
    const Json& listed = report.array_at("arrays");
    REQUIRE(listed.size() == 2);
    CHECK(listed.at(0).string_at("name") == "positions");
    CHECK(listed.at(0).string_at("file") == dir.path("case.positions.f32").string());
    CHECK(listed.at(0).int_at("components") == 4);
    CHECK(listed.at(0).int_at("count") == 2);
    CHECK(listed.at(1).string_at("name") == "ids");
    CHECK(listed.at(1).int_at("count") == 3);
}

TEST_CASE("render: no arrays and no arrays key, and a malformed array is the lab's own error", "[lab]") {
    test::TempDir dir;
    REQUIRE(render({}, dir.path("plain.png")) == 0);
    CHECK_FALSE(read_json_file(dir.path("plain.json")).contains("arrays"));
    CHECK(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()) == 2);  // the PNG and its JSON

    CHECK(render({{"Bad-Name", 4, {1, 2, 3, 4}}}, dir.path("bad.png")) == kExitError);
    CHECK_FALSE(fs::exists(dir.path("bad.json")));
    CHECK(render({{"ragged", 4, {1, 2, 3}}}, dir.path("ragged.png")) == kExitError);
    // A file that cannot be written: a folder in its place.
    fs::create_directories(dir.path("blocked.positions.f32"));
    CHECK(render({{"positions", 1, {1}}}, dir.path("blocked.png")) == kExitError);
}
