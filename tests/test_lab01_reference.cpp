// Lab 01's solution checked against an independent reference: a CPU ray tracer in double precision.
//
// Why this test exists: the lab's own cases compare the GPU image with stored images the same
// shaders produced, so a mistake in the solution (normals not through the inverse transpose, a
// missing renormalize, back faces lit from the wrong side, Gooch's warm and cool swapped, a NaN where
// the light touches the surface) would be baked into the references too. Here nothing comes from the
// GPU path except the image under test: the eye rays come from the same OrbitCamera matrices, hit an
// exact (not tessellated) sphere, and are shaded by C++ copies of lighting.glsl, phong.glsl and
// gooch.glsl. At mesh_resolution=512 the tessellation is far below 8-bit precision, so the two must
// agree to a few levels wherever a pixel is well inside the sphere's outline.
#include "catch.hpp"
#include "test_support.h"

#include "common/image/image.h"
#include "common/io/json.h"
#include "common/scene/transforms.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using glm::dmat3;
using glm::dmat4;
using glm::dvec3;
using glm::dvec4;

namespace {

constexpr int kSize = 256;             // rendered width and height
constexpr int kMaxChannelDiff = 3;     // allowed difference in 8-bit levels on compared pixels
constexpr double kMinComparedShare = 0.2;  // of the whole image, so no case passes by comparing nothing
constexpr double kMinAbsNdotV = 0.15;  // nearer the outline the rasterized normal is too uncertain
const dvec3 kClearColor(0.32, 0.33, 0.36);  // lab.cpp's glClearColor

// ---------------------------------------------------------------------------------------------
// Running the lab

using gsv::test::TempDir;

std::string shell_quote(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}


struct Render {
    gsv::Image image;
    gsv::Json report;
};

// Renders the solution headless with the given --set overrides (plus mesh_resolution=512). Fails the
// test, rather than skipping it, when the binary is missing or cannot render (no EGL, say).
Render render_solution(const std::vector<std::string>& overrides) {
    const fs::path binary = fs::path(GSV_BINARY_DIR) / "bin" / "lab01_solution";
    if (!fs::exists(binary))
        FAIL("the lab binary " << binary.string() << " does not exist: build the lab01_solution target first");

    TempDir dir;
    const fs::path png = dir.path() / "render.png", json = dir.path() / "render.json", log = dir.path() / "log.txt";
    std::string command = shell_quote(binary.string()) + " render --size " + std::to_string(kSize) + "x" +
                          std::to_string(kSize) + " --frames 1 --warmup 0 --set mesh_resolution=512";
    for (const auto& o : overrides) command += " --set " + shell_quote(o);
    command += " --out " + shell_quote(png.string()) + " --json " + shell_quote(json.string());
    command += " > " + shell_quote(log.string()) + " 2>&1";

    const int status = std::system(command.c_str());
    const int exit_code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
    if (exit_code != 0) {
        const char* meaning = exit_code == 3   ? " (GL feature not available: is EGL / a GL driver present?)"
                              : exit_code == 4 ? " (NaN or Inf in the image)"
                              : exit_code == 1 ? " (error)"
                                               : "";
        FAIL("lab01_solution exited with status " << exit_code << meaning << "\ncommand: " << command
                                                  << "\noutput:\n" << gsv::test::read_text(log));
    }
    Render r;
    r.image = gsv::read_png(png);
    r.report = gsv::read_json_file(json);
    REQUIRE(r.image.width == kSize);
    REQUIRE(r.image.height == kSize);
    return r;
}

// ---------------------------------------------------------------------------------------------
// The parameters the lab actually used, read back from its JSON report (so no default is repeated here)

dvec3 parse_vec3(const std::string& text) {
    std::vector<double> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) values.push_back(std::stod(item));
    if (values.size() != 3) FAIL("'" << text << "' is not an x,y,z vector");
    return dvec3(values[0], values[1], values[2]);
}

struct LabParams {
    std::string shading;  // "phong" or "gooch"
    bool specular = false;
    dvec3 diffuse_color, light_position, scale;
    double blue = 0, yellow = 0, alpha = 0, beta = 0, shininess = 0, specular_strength = 0, cut = 0;
    gsv::OrbitCamera camera;
};

LabParams read_params(const gsv::Json& report) {
    const gsv::Json& p = report.object_at("params");
    // What this reference models: a finely tessellated sphere, lit per fragment, without silhouettes.
    REQUIRE(report.string_at("variant") == "solution");
    REQUIRE(p.string_at("model") == "sphere");
    REQUIRE(p.string_at("shading_rate") == "fragment");
    REQUIRE(p.string_at("silhouette") == "off");
    REQUIRE(std::stoi(p.string_at("mesh_resolution")) >= 512);

    const auto number = [&](const char* name) { return std::stod(p.string_at(name)); };
    LabParams lp;
    lp.shading = p.string_at("shading");
    lp.specular = p.string_at("specular") == "on";
    lp.diffuse_color = parse_vec3(p.string_at("diffuse_color"));
    lp.light_position = parse_vec3(p.string_at("light_position"));
    lp.scale = parse_vec3(p.string_at("scale"));
    lp.blue = number("blue");
    lp.yellow = number("yellow");
    lp.alpha = number("alpha");
    lp.beta = number("beta");
    lp.shininess = number("shininess");
    lp.specular_strength = number("specular_strength");
    lp.cut = number("cut");
    lp.camera.yaw_degrees = static_cast<float>(number("camera_yaw"));
    lp.camera.pitch_degrees = static_cast<float>(number("camera_pitch"));
    lp.camera.distance = static_cast<float>(number("camera_distance"));
    return lp;
}

// ---------------------------------------------------------------------------------------------
// The shaders, in C++: each function mirrors the GLSL one of the same name, line for line.

// shaders/gsv/math.glsl
dvec3 safe_normalize(dvec3 v, dvec3 fallback) {
    double length_squared = dot(v, v);
    return length_squared > 1e-20 ? v / std::sqrt(length_squared) : fallback;
}

struct Lab01Shader {
    // The uniforms lab.cpp sets, under their GLSL names.
    dvec3 uLightEye, uDiffuseColor;
    double uShininess, uSpecularStrength, uBlue, uYellow, uAlpha, uBeta;
    // The compile-time switches.
    bool SHADING_GOOCH, EFFECT_SPECULAR;

    // phong.glsl
    dvec3 diffuse(dvec3 n, dvec3 l, dvec3 kd) const {
        const double ambient = 0.15;
        return kd * (ambient + (1.0 - ambient) * std::max(dot(n, l), 0.0));
    }

    dvec3 specular(dvec3 n, dvec3 l, dvec3 v) const {
        if (dot(n, l) <= 0.0) return dvec3(0.0);
        dvec3 r = glm::reflect(-l, n);
        return dvec3(uSpecularStrength * std::pow(std::max(dot(r, v), 0.0), uShininess));
    }

    // gooch.glsl: t = 1 towards the light, where the colour is warm.
    dvec3 gooch(dvec3 n, dvec3 l, dvec3 kd) const {
        dvec3 k_cool = dvec3(0.0, 0.0, uBlue) + uAlpha * kd;
        dvec3 k_warm = dvec3(uYellow, uYellow, 0.0) + uBeta * kd;
        double t = 0.5 * (1.0 + dot(n, l));
        return glm::mix(k_cool, k_warm, t);
    }

    // lighting.glsl
    dvec3 shade(dvec3 n, dvec3 eye_position) const {
        dvec3 l = safe_normalize(uLightEye - eye_position, n);
        dvec3 v = safe_normalize(-eye_position, n);
        dvec3 color = SHADING_GOOCH ? gooch(n, l, uDiffuseColor) : diffuse(n, l, uDiffuseColor);
        if (EFFECT_SPECULAR) color += specular(n, l, v);
        return color;
    }
};

// ---------------------------------------------------------------------------------------------
// The reference image: one eye ray per pixel centre against the exact scaled, cut-open sphere

struct RefPixel {
    bool covered = false;    // the ray hits the visible part of the sphere
    bool back_face = false;  // ... on its inside, seen through the cut
    double n_dot_v = 0;      // with n already flipped towards the viewer
    double n_dot_l = 0;
    dvec3 color{0.0};        // unclamped, unrounded
};

struct Reference {
    int width = 0, height = 0;
    std::vector<RefPixel> pixels;
    const RefPixel& at(int x, int y) const { return pixels[static_cast<std::size_t>(y * width + x)]; }
};

Reference trace_reference(const LabParams& p, int width, int height) {
    // The matrices lab.cpp draws with, widened to double before anything is inverted.
    const dmat4 model = glm::scale(dmat4(1.0), p.scale);
    const dmat4 view = dmat4(p.camera.view());
    const dmat4 projection = dmat4(p.camera.projection(static_cast<float>(width) / static_cast<float>(height)));
    const dmat4 clip_to_world = glm::inverse(projection * view);
    const dmat4 world_to_object = glm::inverse(model);
    const dmat4 model_view = view * model;
    const dmat3 normal_matrix = glm::transpose(glm::inverse(dmat3(model_view)));

    Lab01Shader shader;
    shader.uLightEye = dvec3(view * dvec4(p.light_position, 1.0));
    shader.uDiffuseColor = p.diffuse_color;
    shader.uShininess = p.shininess;
    shader.uSpecularStrength = p.specular_strength;
    shader.uBlue = p.blue;
    shader.uYellow = p.yellow;
    shader.uAlpha = p.alpha;
    shader.uBeta = p.beta;
    shader.SHADING_GOOCH = p.shading == "gooch";
    shader.EFFECT_SPECULAR = p.specular;

    Reference ref;
    ref.width = width;
    ref.height = height;
    ref.pixels.resize(static_cast<std::size_t>(width * height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            // Row 0 is the top of the PNG. The ray runs from the near plane towards the far plane.
            const double ndc_x = (x + 0.5) / width * 2.0 - 1.0, ndc_y = 1.0 - (y + 0.5) / height * 2.0;
            dvec4 near_point = clip_to_world * dvec4(ndc_x, ndc_y, -1.0, 1.0);
            dvec4 far_point = clip_to_world * dvec4(ndc_x, ndc_y, 1.0, 1.0);
            near_point /= near_point.w;
            far_point /= far_point.w;
            const dvec3 origin = dvec3(world_to_object * near_point);
            const dvec3 direction = dvec3(world_to_object * (far_point - near_point));

            // |origin + t direction| = 1, nearest root first; the lab discards object x > cut.
            const double a = dot(direction, direction), b = dot(origin, direction), c = dot(origin, origin) - 1.0;
            const double discriminant = b * b - a * c;
            if (discriminant < 0) continue;
            const double root = std::sqrt(discriminant);
            for (const double t : {(-b - root) / a, (-b + root) / a}) {
                const dvec3 object_point = origin + t * direction;
                if (t < 0 || object_point.x > p.cut) continue;
                RefPixel& px = ref.pixels[static_cast<std::size_t>(y * width + x)];
                const dvec3 eye_position = dvec3(model_view * dvec4(object_point, 1.0));
                dvec3 n = glm::normalize(normal_matrix * object_point);  // the unit sphere's normal is its point
                const dvec3 v = glm::normalize(-eye_position);
                px.covered = true;
                px.back_face = dot(n, v) < 0;
                if (px.back_face) n = -n;  // shade.frag: if (!gl_FrontFacing) n = -n;
                px.n_dot_v = dot(n, v);
                px.n_dot_l = dot(n, safe_normalize(shader.uLightEye - eye_position, n));
                px.color = shader.shade(n, eye_position);
                break;
            }
        }
    return ref;
}

// to_rgba8 in common/image/image.cpp: clamp, then round to the nearest of 256 levels.
int to_level(double value) { return static_cast<int>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0)); }

// Compared: well inside the outline, on one side of the surface (the whole 3x3 neighbourhood is
// covered, and by the same side: the rasterized edges, the cut's rim included, can move by a pixel)
// and not grazing.
bool compared(const Reference& ref, int x, int y) {
    if (x < 1 || y < 1 || x >= ref.width - 1 || y >= ref.height - 1) return false;
    const RefPixel& centre = ref.at(x, y);
    if (!centre.covered || std::abs(centre.n_dot_v) <= kMinAbsNdotV) return false;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const RefPixel& q = ref.at(x + dx, y + dy);
            if (!q.covered || q.back_face != centre.back_face) return false;
        }
    return true;
}

struct Comparison {
    long compared = 0, total = 0;
    int worst_diff = 0;
    int worst_x = -1, worst_y = -1;
    int expected[3] = {0, 0, 0}, actual[3] = {0, 0, 0};
    long background_compared = 0;
    int worst_background_diff = 0;

    std::string describe() const {
        std::ostringstream out;
        out << "compared " << compared << " of " << total << " pixels ("
            << 100.0 * static_cast<double>(compared) / static_cast<double>(total) << "%), worst channel difference "
            << worst_diff;
        if (worst_x >= 0)
            out << " at pixel (" << worst_x << ", " << worst_y << ") [row 0 = top]: expected (" << expected[0] << ", "
                << expected[1] << ", " << expected[2] << "), actual (" << actual[0] << ", " << actual[1] << ", "
                << actual[2] << ")";
        out << "; background: " << background_compared << " pixels, worst difference " << worst_background_diff;
        return out.str();
    }
};

Comparison compare(const Reference& ref, const gsv::Image& image) {
    Comparison result;
    result.total = static_cast<long>(ref.width) * ref.height;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            const std::uint8_t* actual = image.at(x, y);
            bool background = x >= 1 && y >= 1 && x < ref.width - 1 && y < ref.height - 1;
            for (int dy = -1; background && dy <= 1; ++dy)
                for (int dx = -1; background && dx <= 1; ++dx) background = !ref.at(x + dx, y + dy).covered;
            if (background) {
                ++result.background_compared;
                for (int c = 0; c < 3; ++c)
                    result.worst_background_diff =
                        std::max(result.worst_background_diff, std::abs(int(actual[c]) - to_level(kClearColor[c])));
                continue;
            }
            if (!compared(ref, x, y)) continue;
            ++result.compared;
            const dvec3& color = ref.at(x, y).color;
            int diff = 0;
            for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(int(actual[c]) - to_level(color[c])));
            if (diff > result.worst_diff || result.worst_x < 0) {
                result.worst_diff = diff;
                result.worst_x = x;
                result.worst_y = y;
                for (int c = 0; c < 3; ++c) {
                    result.expected[c] = to_level(color[c]);
                    result.actual[c] = actual[c];
                }
            }
        }
    return result;
}

long count_magenta(const gsv::Image& image) {
    long count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* px = image.at(x, y);
            if (px[0] == 255 && px[1] == 0 && px[2] == 255) ++count;
        }
    return count;
}

// Renders the solution with `overrides`, traces the reference from the parameters it reports, and
// requires the two to agree.
Comparison check_against_reference(const std::vector<std::string>& overrides) {
    const Render render = render_solution(overrides);
    const LabParams params = read_params(render.report);
    const Reference ref = trace_reference(params, render.image.width, render.image.height);
    const Comparison result = compare(ref, render.image);
    INFO("lab01_solution render --set mesh_resolution=512" << [&] {
        std::string s;
        for (const auto& o : overrides) s += " --set " + o;
        return s;
    }());
    INFO(result.describe());
    CHECK(render.report.number_at("nan_pixels") == 0);
    CHECK(count_magenta(render.image) == 0);
    CHECK(result.compared >= static_cast<long>(kMinComparedShare * static_cast<double>(result.total)));
    CHECK(result.worst_diff <= kMaxChannelDiff);
    CHECK(result.worst_background_diff <= 1);
    return result;
}

}  // namespace

TEST_CASE("lab01 reference: default Gooch sphere matches the CPU ray tracer", "[unit]") {
    check_against_reference({});
}

TEST_CASE("lab01 reference: Phong sphere matches the CPU ray tracer", "[unit]") {
    check_against_reference({"shading=phong"});
}

TEST_CASE("lab01 reference: non-uniform scale lights with inverse-transpose normals", "[unit]") {
    check_against_reference({"scale=1.3,0.6,1"});
}

TEST_CASE("lab01 reference: uniform scale renormalizes the shortened normals", "[unit]") {
    // The normal matrix of a uniform scale by 1.5 shortens normals to 2/3: unrenormalized, diffuse
    // and specular both come out visibly darker.
    check_against_reference({"scale=1.5,1.5,1.5", "shading=phong"});
}

TEST_CASE("lab01 reference: cut-open sphere lights its back faces from their own side", "[unit]") {
    check_against_reference({"cut=0.25", "camera_yaw=70"});
}

TEST_CASE("lab01 reference: a light touching the surface or at the eye gives no NaN", "[unit]") {
    SECTION("light on the surface point that faces the camera") {
        // The eye sits on +z (yaw 0, pitch 0), so the unit sphere's point (0,0,1) faces it.
        check_against_reference({"camera_yaw=0", "camera_pitch=0", "light_position=0,0,1"});
    }
    SECTION("light at the camera position") {
        check_against_reference({"camera_yaw=0", "camera_pitch=0", "camera_distance=3.4", "light_position=0,0,3.4",
                                 "shading=phong"});
    }
}

TEST_CASE("lab01 reference: Gooch is warm towards the light and cool away from it", "[unit]") {
    const Render render = render_solution({});
    const LabParams params = read_params(render.report);
    REQUIRE(params.shading == "gooch");
    const Reference ref = trace_reference(params, render.image.width, render.image.height);

    // Mean (R - B) of the rendered image, in 8-bit levels, over the compared pixels facing towards
    // the light and over those facing away from it.
    double lit_sum = 0, unlit_sum = 0;
    long lit = 0, unlit = 0;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            if (!compared(ref, x, y)) continue;
            const std::uint8_t* px = render.image.at(x, y);
            const double r_minus_b = double(px[0]) - double(px[2]);
            if (ref.at(x, y).n_dot_l > 0.5) lit_sum += r_minus_b, ++lit;
            if (ref.at(x, y).n_dot_l < -0.5) unlit_sum += r_minus_b, ++unlit;
        }
    REQUIRE(lit >= 100);
    REQUIRE(unlit >= 100);
    const double lit_mean = lit_sum / double(lit), unlit_mean = unlit_sum / double(unlit);
    INFO("mean R-B facing the light (n.l > 0.5): " << lit_mean << " over " << lit << " pixels; facing away (n.l < -0.5): "
                                                    << unlit_mean << " over " << unlit << " pixels");
    CHECK(lit_mean > 0.0);
    CHECK(unlit_mean < lit_mean - 0.3 * 255.0);
}

TEST_CASE("lab01 reference: the comparison notices a light moved by half a unit", "[unit]") {
    // Not vacuous: the reference for a slightly different light must disagree with the rendered image.
    const Render render = render_solution({});
    LabParams params = read_params(render.report);
    params.light_position += dvec3(0.0, 0.0, 0.5);
    const Comparison result = compare(trace_reference(params, render.image.width, render.image.height), render.image);
    INFO(result.describe());
    CHECK(result.worst_diff > 4 * kMaxChannelDiff);
}
