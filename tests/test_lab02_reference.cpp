// Lab 02's solution checked against an independent reference: line integral convolution on the CPU in
// double precision.
//
// Why this test exists: the lab's grading cases compare the GPU image with stored images the same
// shaders produced, so a mistake in the solution (a backward loop that steps forward, samples past the
// border counted, a midpoint step that is really Euler, a NaN at a zero of the field) would be baked into
// the references too. Here nothing comes from the GPU path except the image under test: the flow and
// the noise are made again with gsv::make_flow and gsv::white_noise, and the shaders (lic.frag,
// streamline.glsl, math.glsl's safeNormalize) run in C++ on top of an emulation of the sampler state
// lab.cpp sets: GL_LINEAR with GL_CLAMP_TO_EDGE on float textures.
//
// LIC is unforgiving to compare: a streamline that starts a hair away from the CPU's (float texture
// coordinates, the rasterizer's interpolation, the driver's filtering) may cross into other noise
// texels, and the white noise turns any such difference into a full-size one for that sample. So the
// bounds below are statistical (mean difference, share of pixels off by more than a few levels), set
// from what llvmpipe measures with margin, and proved tight enough by rendering deliberately broken
// copies of the shaders that must fail them.
#include "catch.hpp"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "test_support.h"

#include "common/image/image.h"
#include "common/io/json.h"
#include "support/flow/flow_field.h"
#include "support/flow/noise.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using glm::dvec2;

namespace {

constexpr int kSize = 96;  // rendered width and height: small, so the CPU reference and llvmpipe are quick

// ---------------------------------------------------------------------------------------------
// Running the lab

struct Render {
    gsv::Image image;
    gsv::Json report;
};

std::string describe_command(const std::vector<std::string>& overrides, int size = kSize) {
    std::string s = "lab02_solution render --size " + std::to_string(size) + "x" + std::to_string(size);
    for (const auto& o : overrides) s += " --set " + o;
    return s;
}

// Renders lab02_solution headless with the given --set overrides. `kit_root`, when given, is a copy of
// the kit's files (GSV_ROOT) whose shaders have been broken on purpose. Fails the test, rather than
// skipping it, when the binary is missing or cannot render (no EGL, say), or when the image holds a NaN
// (status 4): no zero of the field may produce one.
Render render_solution(const std::vector<std::string>& overrides, const fs::path& kit_root = {}, int size = kSize) {
    if (!fs::exists(gsv::test::bin_dir() / "lab02_solution"))
        FAIL("lab02_solution does not exist in " << gsv::test::bin_dir().string() << ": build it first");
    gsv::test::TempDir dir;
    std::vector<std::string> args{"render", "--size", std::to_string(size) + "x" + std::to_string(size),
                                  "--frames", "1", "--warmup", "0", "--out", dir.path("lic.png").string()};
    for (const auto& o : overrides) {
        args.push_back("--set");
        args.push_back(o);
    }
    std::vector<std::string> environment;
    if (!kit_root.empty()) environment.push_back("GSV_ROOT=" + kit_root.string());
    const gsv::test::LabRun run = gsv::test::run_lab("lab02_solution", args, dir.path(), environment);
    INFO(describe_command(overrides, size) << "\noutput:\n" << run.process.output);
    REQUIRE(run.exit_code() == 0);  // 4 would be NaN or Inf in the image
    Render r;
    r.image = gsv::read_png(dir.path("lic.png"));
    r.report = gsv::read_json_file(dir.path("lic.json"));
    REQUIRE(r.image.width == size);
    REQUIRE(r.image.height == size);
    REQUIRE(r.report.number_at("nan_pixels") == 0);
    REQUIRE(r.report.number_at("inf_pixels") == 0);
    return r;
}

// ---------------------------------------------------------------------------------------------
// The parameters the lab actually used, read back from its JSON report (so no default is repeated here)

struct LicParams {
    std::string field;
    int length = 0;
    bool midpoint = false, normalized = false;
    double speed = 0, time = 0;
    std::uint64_t seed = 0;
};

LicParams read_params(const gsv::Json& report) {
    const gsv::Json& p = report.object_at("params");
    // What this reference models: white noise smeared along an analytic field.
    REQUIRE(report.string_at("variant") == "solution");
    REQUIRE(p.string_at("input") == "noise");
    LicParams lp;
    lp.field = p.string_at("field");
    REQUIRE(lp.field != "file");
    REQUIRE(lp.field != "swirl");
    lp.length = std::stoi(p.string_at("length"));
    lp.midpoint = p.string_at("step") == "midpoint";
    lp.normalized = p.string_at("normalized") == "on";
    lp.speed = std::stod(p.string_at("speed"));
    lp.time = std::stod(p.string_at("time"));
    lp.seed = static_cast<std::uint64_t>(std::stoll(p.string_at("seed")));
    return lp;
}

// ---------------------------------------------------------------------------------------------
// The sampler: GL_LINEAR with GL_CLAMP_TO_EDGE on a float texture, in double
//
// Texel i of a texture n texels wide has its centre at s = (i + 0.5) / n. A lookup at s blends the two
// texels whose centres bracket u = s n - 0.5 by the fraction of u past the lower one; with
// CLAMP_TO_EDGE an index outside 0..n-1 reads the edge texel, so beyond the outer centres the value is
// flat. (The same in both axes; the texture's row 0 is its bottom row, t = 0.)

struct Bilinear {
    int i0, i1, j0, j1;
    double a, b;  // weights of i1 and j1
};

Bilinear bilinear(dvec2 st, int width, int height) {
    const double u = st.x * width - 0.5, v = st.y * height - 0.5;
    const double fu = std::floor(u), fv = std::floor(v);
    Bilinear w;
    w.a = u - fu;
    w.b = v - fv;
    // Clamp before converting: a position far outside must not overflow an int.
    const auto index = [](double f, int n) { return static_cast<int>(std::clamp(f, -1.0, double(n))); };
    const int iu = index(fu, width), iv = index(fv, height);
    w.i0 = std::clamp(iu, 0, width - 1);
    w.i1 = std::clamp(iu + 1, 0, width - 1);
    w.j0 = std::clamp(iv, 0, height - 1);
    w.j1 = std::clamp(iv + 1, 0, height - 1);
    return w;
}

// ---------------------------------------------------------------------------------------------
// The shaders, in C++: each function mirrors the GLSL one of the same name.

// What the CPU found for one pixel: its colour before quantisation, and how many samples it averaged.
struct LicPixel {
    double value = 0;
    int count = 0;
    bool left_field = false;  // a streamline through it ended at the border before its full length
    bool meets_zero = false;  // with normalised steps, a sample lies on a zero of the field (see below)
};

// With normalised steps, a streamline that lands on a zero of the field is decided by rounding: where the
// exact step lands on the zero, the double-precision position is within about 1e-15 texels of it and
// |v|^2 falls below safe_normalize's 1e-20, so it stays put; the GPU's float position is off by some
// 1e-6 to 1e-5 texels, |v|^2 is around 1e-14, and it takes a unit step wherever that error points.
// (On the source at 97x97 this is every pixel at a whole number of texels from the centre along a
// Pythagorean direction: (3, 4), (5, 12), (8, 15)...) Such pixels are counted and set apart; they are
// no error of either side. A sample counts as on a zero where |v| is below this share of the field's
// largest speed: 1e-4 of it is 0.007 texels from the source's centre at 97x97.
constexpr double kNearZeroSpeed = 1e-4;

class CpuLic {
public:
    // The same textures lab.cpp's make_textures builds: one flow texel and one noise texel per pixel.
    CpuLic(const LicParams& p, int width, int height)
        : p_(p), width_(width), height_(height),
          flow_(gsv::make_flow(gsv::flow_kind_from_name(p.field), width, height, p.speed, p.time, p.seed)),
          noise_(gsv::white_noise(width, height, p.seed)), near_zero_(kNearZeroSpeed * flow_.max_speed()) {}

    // streamline.glsl
    dvec2 flow_at(dvec2 st) const {
        const Bilinear w = bilinear(st, flow_.width, flow_.height);
        const auto texel = [&](int i, int j) { return dvec2(flow_.at(i, j)); };
        return glm::mix(glm::mix(texel(w.i0, w.j0), texel(w.i1, w.j0), w.a),
                        glm::mix(texel(w.i0, w.j1), texel(w.i1, w.j1), w.a), w.b);
    }

    // math.glsl's safeNormalize with the fallback step_direction gives it: no step at a zero.
    dvec2 step_direction(dvec2 v) const {
        if (!p_.normalized) return v;
        const double length_squared = glm::dot(v, v);
        return length_squared > 1e-20 ? v / std::sqrt(length_squared) : dvec2(0.0);
    }

    dvec2 advance(dvec2 st, double direction, dvec2 texel) const {
        if (p_.midpoint) {
            const dvec2 half_step = st + 0.5 * direction * step_direction(flow_at(st)) * texel;
            return st + direction * step_direction(flow_at(half_step)) * texel;
        }
        return st + direction * step_direction(flow_at(st)) * texel;
    }

    // [0,1]^2, edges included, as greaterThanEqual / lessThanEqual test it.
    static bool streamline_continues(dvec2 st) {
        return st.x >= 0.0 && st.x <= 1.0 && st.y >= 0.0 && st.y <= 1.0;
    }

    // The noise, grey in all three channels of the input texture: one channel is enough.
    double input_at(dvec2 st) const {
        const Bilinear w = bilinear(st, width_, height_);
        const auto texel = [&](int i, int j) { return double(noise_[static_cast<std::size_t>(j * width_ + i)]); };
        return glm::mix(glm::mix(texel(w.i0, w.j0), texel(w.i1, w.j0), w.a),
                        glm::mix(texel(w.i0, w.j1), texel(w.i1, w.j1), w.a), w.b);
    }

    // lic.frag's main() for the pixel (x, y), y counted from the BOTTOM as GL counts it; vTexCoord is the
    // pixel's centre (fullscreen.vert maps the quad's [-1,1]^2 onto [0,1]^2).
    LicPixel pixel(int x, int y) const {
        const dvec2 texel = 1.0 / dvec2(flow_.width, flow_.height);
        const dvec2 tex_coord((x + 0.5) / width_, (y + 0.5) / height_);
        LicPixel out;
        double sum = input_at(tex_coord);
        int count = 1;  // the pixel's own sample
        for (const double direction : {+1.0, -1.0}) {
            dvec2 st = tex_coord;
            for (int i = 0; i < p_.length; ++i) {
                st = advance(st, direction, texel);
                if (!streamline_continues(st)) {
                    out.left_field = true;
                    break;
                }
                sum += input_at(st);
                count += 1;
                if (p_.normalized && glm::length(flow_at(st)) < near_zero_) out.meets_zero = true;
            }
        }
        out.value = sum / count;
        out.count = count;
        return out;
    }

private:
    LicParams p_;
    int width_, height_;
    gsv::FlowField flow_;
    std::vector<float> noise_;
    double near_zero_;
};

// The whole image, stored like a PNG (row 0 at the top).
std::vector<LicPixel> cpu_image(const CpuLic& lic, int width, int height) {
    std::vector<LicPixel> image(static_cast<std::size_t>(width * height));
    for (int row = 0; row < height; ++row)
        for (int x = 0; x < width; ++x)
            image[static_cast<std::size_t>(row * width + x)] = lic.pixel(x, height - 1 - row);
    return image;
}

// to_rgba8 in common/image/image.cpp: clamp, then round to the nearest of 256 levels.
int to_level(double value) { return static_cast<int>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0)); }

// ---------------------------------------------------------------------------------------------
// Comparing

struct Difference {
    long pixels = 0;
    int max = 0;
    double mean = 0;
    double over[4] = {0, 0, 0, 0};  // share of pixels more than kLevels[k] levels off
    static constexpr int kLevels[4] = {1, 2, 4, 8};

    std::string describe() const {
        std::ostringstream out;
        out << pixels << " pixels: max " << max << " levels, mean " << mean;
        for (int k = 0; k < 4; ++k) out << ", >" << kLevels[k] << ": " << 100.0 * over[k] << "%";
        return out.str();
    }
};

// Differences in 8-bit levels of the red channel (the three are equal, the noise being grey) over the
// pixels `which` selects.
template <typename Which>
Difference difference(const std::vector<LicPixel>& expected, const gsv::Image& actual, Which which) {
    Difference d;
    long sum = 0, over[4] = {0, 0, 0, 0};
    for (int row = 0; row < actual.height; ++row)
        for (int x = 0; x < actual.width; ++x) {
            const LicPixel& e = expected[static_cast<std::size_t>(row * actual.width + x)];
            if (!which(e)) continue;
            const int diff = std::abs(int(actual.at(x, row)[0]) - to_level(e.value));
            ++d.pixels;
            sum += diff;
            d.max = std::max(d.max, diff);
            for (int k = 0; k < 4; ++k) over[k] += diff > Difference::kLevels[k];
        }
    if (d.pixels > 0) {
        d.mean = double(sum) / double(d.pixels);
        for (int k = 0; k < 4; ++k) d.over[k] = double(over[k]) / double(d.pixels);
    }
    return d;
}

Difference difference(const std::vector<LicPixel>& expected, const gsv::Image& actual) {
    return difference(expected, actual, [](const LicPixel&) { return true; });
}

// The bound every case must meet. On llvmpipe (Mesa 22.3, 96x96) the solution and this reference agree
// to the level on all but a handful of pixels: at most 1 level off and a mean under 0.001 level in every
// case below (the pixels set apart as meeting a zero excepted), so llvmpipe filters float textures at
// (about) float precision. A GPU that quantises its filtering weights to 8 bits would shift a sample by
// up to 1/512 texel, which the bound leaves room for many times over. The broken shaders below measure
// a mean of 1.5 to 11 levels and 20% to 83% of pixels more than 2 levels off: each fails both halves of
// the bound on its own.
constexpr double kMaxMeanDiff = 0.25;          // levels
constexpr double kMaxShareOver2Levels = 0.01;  // of the pixels compared

bool within_bound(const Difference& d) { return d.mean <= kMaxMeanDiff && d.over[1] <= kMaxShareOver2Levels; }

struct Checked {
    Render render;
    LicParams params;
    std::vector<LicPixel> expected;
    Difference all;
};

// Renders the solution with `overrides`, runs the CPU LIC with the parameters it reports, and measures
// the difference.
Checked compare_with_reference(const std::vector<std::string>& overrides, const fs::path& kit_root = {},
                               int size = kSize) {
    Checked c;
    c.render = render_solution(overrides, kit_root, size);
    c.params = read_params(c.render.report);
    c.expected = cpu_image(CpuLic(c.params, size, size), size, size);
    c.all = difference(c.expected, c.render.image);
    return c;
}

// How many pixels of the rendered image are exactly their own noise texel, in 8-bit levels: what an image
// must be whose streamlines never move.
long pixels_equal_to_noise(const Checked& c) {
    const int width = c.render.image.width, height = c.render.image.height;
    const std::vector<float> noise = gsv::white_noise(width, height, c.params.seed);
    long equal = 0;
    for (int row = 0; row < height; ++row)
        for (int x = 0; x < width; ++x)
            equal += c.render.image.at(x, row)[0] ==
                     to_level(noise[static_cast<std::size_t>((height - 1 - row) * width + x)]);
    return equal;
}

Checked check_against_reference(const std::vector<std::string>& overrides, int size = kSize) {
    Checked c = compare_with_reference(overrides, {}, size);
    INFO(describe_command(overrides, size) << "\n" << c.all.describe());
    CHECK(c.all.pixels == long(size) * size);
    CHECK(within_bound(c.all));
    for (const LicPixel& p : c.expected) REQUIRE(p.count >= 1);
    return c;
}

// ---------------------------------------------------------------------------------------------
// Broken copies of the solution's shaders, which the comparison must reject

// What lab02_solution loads (its shaders, the kit's shader library and the photograph it reads at
// start-up), copied into `root` so that one line can be broken; GSV_ROOT points the binary at the copy.
void copy_of_lab02(const fs::path& root) {
    const fs::path source = gsv::test::source_root();
    gsv::test::copy_lab_kit(source, root, "lab02_lic");
    fs::copy(source / "data" / "images", root / "data" / "images", fs::copy_options::recursive);
}

}  // namespace

// ---------------------------------------------------------------------------------------------

TEST_CASE("lab02 reference: the rotation, Euler steps, matches the CPU LIC", "[lab][lab02]") {
    check_against_reference({"field=rotation", "length=25"});
}

TEST_CASE("lab02 reference: a source's streamlines leave the field, and samples outside are not counted", "[lab][lab02]") {
    const Checked c = check_against_reference({"field=source", "length=40"});
    // The case is a border case: most streamlines end early, and those pixels agree as well as the rest.
    long left = 0;
    for (const LicPixel& p : c.expected) left += p.left_field;
    CHECK(left > long(kSize) * kSize / 2);
    const Difference at_border = difference(c.expected, c.render.image, [](const LicPixel& p) { return p.left_field; });
    INFO("pixels whose streamline left the field: " << at_border.describe());
    CHECK(within_bound(at_border));
    // The image's corners see only the outward half of their streamlines cut off: their count is the
    // backward half plus the one or two forward steps before the border.
    const LicPixel& corner = c.expected.front();
    CHECK(corner.count < c.params.length + 4);
    CHECK(corner.count > c.params.length);
}

TEST_CASE("lab02 reference: the saddle and the double gyre match the CPU LIC", "[lab][lab02]") {
    SECTION("saddle") { check_against_reference({"field=saddle"}); }
    SECTION("double gyre") { check_against_reference({"field=double_gyre", "time=2.5"}); }
}

TEST_CASE("lab02 reference: midpoint steps at length 80 match the CPU LIC", "[lab][lab02]") {
    check_against_reference({"field=rotation", "step=midpoint", "length=80"});
}

TEST_CASE("lab02 reference: normalised steps through the source's zero give no NaN and match", "[lab][lab02]") {
    // At the centre the field vanishes: safe_normalize must stay put there instead of dividing by zero.
    // On an even grid the zero lies between four texels, and streamlines flowing into it (backwards)
    // hop around it; on an odd grid it is the middle texel itself, exactly 0, under a pixel centre.
    for (const int size : {kSize, kSize + 1}) {
        DYNAMIC_SECTION(size << "x" << size) {
            const Checked c = compare_with_reference({"field=source", "normalized=on"}, {}, size);
            long on_zero = 0;
            for (const LicPixel& p : c.expected) on_zero += p.meets_zero;
            const Difference rest =
                difference(c.expected, c.render.image, [](const LicPixel& p) { return !p.meets_zero; });
            const Difference decided_by_rounding =
                difference(c.expected, c.render.image, [](const LicPixel& p) { return p.meets_zero; });
            INFO(describe_command({"field=source", "normalized=on"}, size) << "\nall: " << c.all.describe()
                                                                             << "\noff the zero: " << rest.describe()
                                                                             << "\nthrough the zero: "
                                                                             << decided_by_rounding.describe());
            CHECK(within_bound(rest));
            CHECK(on_zero <= long(size) * size / 20);  // few enough that the comparison still means something
            for (const LicPixel& p : c.expected) REQUIRE(p.count >= 1);
            if (size % 2 == 1) {
                // The middle pixel sits on the zero itself, exactly 0: it stays put, every sample its own.
                const LicPixel& centre = c.expected[static_cast<std::size_t>(size * size / 2)];
                CHECK(centre.count == 2 * c.params.length + 1);
                CHECK(centre.meets_zero);
                CHECK(on_zero > 0);
            }
        }
    }
}

TEST_CASE("lab02 reference: a field of zeros leaves the noise itself, with no NaN", "[lab][lab02]") {
    // speed=0 scales every velocity to exactly 0: every step stays on the pixel's centre, so each of the
    // 2 length + 1 samples is the pixel's own noise texel and the average is that texel.
    for (const char* normalized : {"normalized=off", "normalized=on"}) {
        const Checked c = check_against_reference({"field=source", "speed=0", "length=25", normalized});
        INFO(normalized << ": " << c.all.describe());
        CHECK(c.all.max <= 1);
        // A float sum of 51 equal values divided by 51 may miss the value by an ulp, and so round to the
        // next level where it sits on a half: allow for one pixel in a hundred.
        CHECK(pixels_equal_to_noise(c) >= long(kSize) * kSize * 99 / 100);
        for (const LicPixel& p : c.expected) REQUIRE(p.count == 2 * c.params.length + 1);
    }
}

TEST_CASE("lab02 reference: a tiny velocity neither divides by zero nor moves the samples", "[lab][lab02]") {
    SECTION("Euler steps of a millionth of a texel") {
        // 25 steps each way move a sample by at most 2.5e-5 texels: every pixel is its own noise texel.
        const Checked c = check_against_reference({"field=rotation", "speed=0.000001"});
        INFO(c.all.describe());
        CHECK(c.all.max <= 1);
        CHECK(pixels_equal_to_noise(c) >= long(kSize) * kSize * 99 / 100);
    }
    SECTION("normalised steps below safe_normalize's threshold stay put") {
        // Speeds of at most 1e-12 texels per step: |v|^2 <= 1e-24 < 1e-20, so no direction and no step.
        // (Above the threshold the same field would be smeared into full-length circles.)
        const Checked c = check_against_reference({"field=rotation", "speed=1e-12", "normalized=on"});
        INFO(c.all.describe());
        CHECK(c.all.max <= 1);
        CHECK(pixels_equal_to_noise(c) >= long(kSize) * kSize * 99 / 100);
    }
}

TEST_CASE("lab02 reference: the comparison rejects a backward loop that steps forward, samples past the border, "
          "Euler posing as midpoint, and normalisation ignored",
          "[lab][lab02]") {
    // Each broken copy differs from the solution by one line; rendered, it must fall outside the bound
    // that the solution meets.
    struct Broken {
        const char* name;
        const char* file;
        const char* from;
        const char* to;
        std::vector<std::string> overrides;
    };
    const Broken broken[] = {
        // Bailey's listing: every streak one-sided, the forward half counted twice.
        {"backward-steps-forward", "lic.frag", "st = advance(st, -1.0, texel);", "st = advance(st, +1.0, texel);",
         {"field=rotation", "length=25"}},
        // The clamped border texel smeared into a streak and counted.
        {"counts-outside", "streamline.glsl",
         "return all(greaterThanEqual(st, vec2(0.0))) && all(lessThanEqual(st, vec2(1.0)));", "return true;",
         {"field=source", "length=40"}},
        // The half step computed and then ignored: Euler with the midpoint's name.
        {"midpoint-is-euler", "streamline.glsl", "stepDirection(flowAt(halfStep))", "stepDirection(flowAt(st))",
         {"field=rotation", "step=midpoint", "length=80"}},
        // normalized=on ignored (the starter's stepDirection): slow regions keep their short streaks.
        {"normalized-ignored", "streamline.glsl", "return safeNormalize(v, vec2(0.0));", "return v;",
         {"field=source", "normalized=on"}},
    };
    for (const Broken& b : broken) {
        DYNAMIC_SECTION(b.name) {
            const gsv::test::TempDir root;
            copy_of_lab02(root.path());
            gsv::test::replace_in_file(root.path() / "solutions" / "lab02_lic" / b.file, b.from, b.to);
            const Checked c = compare_with_reference(b.overrides, root.path());
            INFO(b.name << ": " << describe_command(b.overrides) << "\n" << c.all.describe());
            CHECK(c.all.mean > kMaxMeanDiff);
            CHECK(c.all.over[1] > kMaxShareOver2Levels);
        }
    }
}

TEST_CASE("lab02 reference: midpoint steps keep the rotation's circles closed, Euler spirals out", "[lab][lab02]") {
    // One full turn on the lab's own rotation texture (96x96, speed 1), in double: bilinear filtering
    // reproduces the linear field (-y, x) exactly inside the texture, so what remains is the step's own
    // error. Euler's factor |1 + i w| = sqrt(1 + w^2) per step grows the radius by about pi w per turn
    // (w the angular speed in radians per step); the midpoint's |1 + i w - w^2/2| = sqrt(1 + w^4/4) by
    // about pi w^3 / 4.
    LicParams params;
    params.field = "rotation";
    params.speed = 1.0;
    params.length = 0;
    const dvec2 texel = 1.0 / dvec2(kSize, kSize);
    const dvec2 centre(0.5, 0.5);
    const double radius = 30.0;  // texels: the circle stays inside the field
    const auto drift_after_one_turn = [&](bool midpoint) {
        params.midpoint = midpoint;
        const CpuLic lic(params, kSize, kSize);
        dvec2 st = centre + dvec2(radius, 0.0) * texel;
        // Whole steps until the angle swept reaches a full turn.
        double swept = 0;
        int steps = 0;
        while (swept < 2.0 * std::acos(-1.0)) {
            const dvec2 before = (st - centre) / texel;
            st = lic.advance(st, +1.0, texel);
            const dvec2 after = (st - centre) / texel;
            swept += std::atan2(before.x * after.y - before.y * after.x, glm::dot(before, after));
            REQUIRE(++steps < 10000);
        }
        return glm::length((st - centre) / texel) - radius;  // texels
    };
    const double euler = drift_after_one_turn(false), midpoint = drift_after_one_turn(true);
    INFO("radius drift after one turn from r = 30 texels: Euler " << euler << " texels, midpoint " << midpoint
                                                                   << " texels");
    CHECK(euler > 1.0);                         // Euler: about 4.8% of the radius
    CHECK(std::abs(midpoint) < 1e-3);           // midpoint: about 2e-6 of it
    CHECK(euler > 1000.0 * std::abs(midpoint));
}
