// Lab 06's modular ray caster (solutions/lab06_raycasting/, its module table in raycast_modules.cpp, the machinery in
// support/raycast/raycast_config.h): the module table's promises, a compositing mode added as a GLSL file and a row,
// the generated configuration header, that each configuration compiles only its own modules, and what the shaders draw against
// closed forms and CPU references, including the hard cases (entry == exit, a zero gradient, the
// isosurface's 0/0, opacity correction, early termination). The uber-shader and the hand-written DVR
// must draw what the specialised shader draws.
#include "catch.hpp"
#include "gl_fixture.h"
#include "test_support.h"

#include "common/core/error.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/gl/gpu_mesh.h"
#include "common/gl/texture.h"
#include "common/image/image.h"
#include "common/scene/mesh_data.h"
#include "common/params/params.h"
#include "common/shader/shader_source.h"
#include "solutions/lab06_raycasting/raycast_modules.h"
#include "support/raycast/raycast_components.h"
#include "support/raycast/raycast_config.h"
#include "support/volume/sobel_gradient.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace gsv;
namespace fs = std::filesystem;
using Config = RaycastConfig;
using G = RaycastConfig::Gradient;
using C = RaycastConfig::Classification;
using S = RaycastConfig::Shading;
using K = RaycastConfig::Compositing;

namespace {

const fs::path kShaders = test::source_root() / "shaders";
// The ray caster is lab 06's own: its skeleton and modules sit in the reference solution's folder.
const fs::path kRaycast = test::source_root() / "solutions" / "lab06_raycasting";
// The lab's module table, as the lab reads it (tests/CMakeLists.txt builds its file into the tests).
const RaycastModules& kModules = lab06::raycast_modules();
// Where a mode added by a test keeps its GLSL file (composite_test_avg.glsl).
const fs::path kTestShaders = test::source_root() / "tests" / "shaders";
// That mode's row: all a new compositing mode adds to the lab's table.
const CompositingModule kAverageRow = {{"avg", "composite_test_avg.glsl", "TestAvg"}, "mean intensity, opaque", false, false,
                                       {true, "Each pixel shows the mean intensity on its ray, opaque.", false}};

Config make_config(K compositing, G gradient = G::None, C classification = C::Raw, S shading = S::None,
                   bool early_termination = true) {
    Config c;
    c.compositing = compositing;
    c.gradient = gradient;
    c.classification = classification;
    c.shading = shading;
    c.early_termination = early_termination;
    return c;
}

// Every configuration validate() accepts, with DVR's early termination both on and off.
std::vector<Config> configs_with_termination_off(const RaycastModules& modules = kModules) {
    std::vector<Config> configs = all_raycast_configs(modules);
    for (Config c : all_raycast_configs(modules)) {
        if (c.compositing != K::Dvr) continue;
        c.early_termination = false;
        configs.push_back(c);
    }
    return configs;
}

// The function each module defines, and whether the effective configuration compiles that module in.
struct ModuleFunction {
    std::string name;
    std::function<bool(const Config&)> chosen;
};

const std::vector<ModuleFunction>& module_functions() {
    static const std::vector<ModuleFunction> functions = {
        {"rcGradientForward", [](const Config& c) { return c.gradient == G::Forward; }},
        {"rcGradientCentral", [](const Config& c) { return c.gradient == G::Central; }},
        {"rcGradientPrecomputed", [](const Config& c) { return c.gradient == G::Precomputed; }},
        {"rcClassifyRaw", [](const Config& c) { return c.classification == C::Raw; }},
        {"rcClassifyTf", [](const Config& c) { return c.classification == C::TransferFunction; }},
        {"rcShadePhong", [](const Config& c) { return c.shading == S::Phong; }},
        {"rcCompositeDvr", [](const Config& c) { return c.compositing == K::Dvr; }},
        {"rcCompositeMip", [](const Config& c) { return c.compositing == K::Mip; }},
        {"rcCompositeIso", [](const Config& c) { return c.compositing == K::Isosurface; }},
        {"rcCompositeFhp", [](const Config& c) { return c.compositing == K::FirstHit; }},
    };
    return functions;
}

PreprocessOptions shader_options(GlVersion version = {4, 1}) {
    PreprocessOptions options;
    options.version = version;
    options.include_dirs = {kRaycast, kShaders, kTestShaders};
    return options;
}

ShaderProgram build_program(const Context& context, const std::string& fragment, std::vector<GeneratedFile> generated) {
    ProgramSpec spec;
    spec.name = fragment;
    spec.files = {kShaders / "gsv" / "fullscreen.vert", kRaycast / fragment};
    spec.generated = std::move(generated);
    return ShaderProgram::build(spec, shader_options(context.effective_version()));
}

ShaderProgram specialised(const Context& context, const Config& config, const RaycastModules& modules = kModules) {
    return build_program(context, "raycast.frag", {raycast_config_file(modules, config)});
}

// A cube of n^3 voxels with value f(i, j, k), x fastest.
std::vector<float> make_volume(int n, const std::function<float(int, int, int)>& f) {
    std::vector<float> v(static_cast<std::size_t>(n) * n * n);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) v[(static_cast<std::size_t>(k) * n + j) * n + i] = f(i, j, k);
    return v;
}

// The Sobel gradient at the voxels, neighbours clamped to the grid, unit spacing: what the precomputed gradient
// module reads (lab 06 makes it with the same function).
std::vector<float> precomputed_gradients(int n, const std::vector<float>& v) {
    gsv::Volume volume;
    volume.nx = volume.ny = volume.nz = n;
    volume.values = v;
    volume.name = "test";
    return gsv::sobel_gradient_volume(volume);
}

// Each pixel's ray as entry and exit texture coordinates (RGB) with alpha 1 where it hits, bottom row first.
struct Rays {
    int width = 0, height = 0;
    std::vector<float> entry, exit;
};

Rays make_rays(int width, int height, const std::function<void(float u, float v, glm::vec4& entry, glm::vec4& exit)>& f) {
    Rays rays{width, height, {}, {}};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            glm::vec4 entry(0.0f), exit(0.0f);
            f((x + 0.5f) / width, (y + 0.5f) / height, entry, exit);
            rays.entry.insert(rays.entry.end(), {entry.r, entry.g, entry.b, entry.a});
            rays.exit.insert(rays.exit.end(), {exit.r, exit.g, exit.b, exit.a});
        }
    return rays;
}

// Rays along +z through texel centres: their x and y direction components are exactly 0.
Rays rays_along_z(int n) {
    return make_rays(n, n, [](float u, float v, glm::vec4& entry, glm::vec4& exit) {
        entry = {u, v, 0.0f, 1.0f};
        exit = {u, v, 1.0f, 1.0f};
    });
}

// Oblique rays, a band of pixels the proxy does not cover, and one pixel whose entry equals its exit.
Rays oblique_rays() {
    return make_rays(24, 20, [](float u, float v, glm::vec4& entry, glm::vec4& exit) {
        if (u < 0.1f) return;
        entry = {u, v, 0.02f, 1.0f};
        exit = {1.0f - 0.6f * u, 0.2f + 0.7f * v, 0.97f, 1.0f};
        if (std::abs(u - 5.5f / 24) < 1e-3f && std::abs(v - 5.5f / 20) < 1e-3f) exit = entry;
    });
}

// The uniforms the tests vary; the rest are set to one fixed scene.
struct Settings {
    float step = 1.0f / 16;
    float reference = 0;  // 0: the step itself, no opacity correction
    float threshold = 1.0f;
    float iso = 0.5f;
    glm::vec4 background{0.0f};
    std::vector<std::pair<std::string, int>> modes;  // the uber-shader's
};

struct Rendered {
    ImageF color;              // row 0 = top
    std::vector<float> depth;  // GL's rows: row 0 = bottom
    int width = 0, height = 0;
    const float* pixel(int x, int y_from_bottom) const { return color.at(x, height - 1 - y_from_bottom); }
    float depth_at(int x, int y_from_bottom) const { return depth[static_cast<std::size_t>(y_from_bottom) * width + x]; }
};

// The GL objects one scene needs; the context is declared first so that it goes last.
class Scene {
public:
    Scene(const Rays& rays, int n, const std::vector<float>& volume)
        : context_(test::headless_context()),
          quad_(make_fullscreen_quad(), Profile::Core),
          target_(rays.width, rays.height, ColorFormat::RGBA32F, true) {
        const Sampling nearest{GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE};
        entry_ = Texture::create_2d(rays.width, rays.height, TexelFormat::RGBA32F, rays.entry.data(), nearest);
        exit_ = Texture::create_2d(rays.width, rays.height, TexelFormat::RGBA32F, rays.exit.data(), nearest);
        volume_ = Texture::create_3d(n, n, n, TexelFormat::R32F, volume.data());
        const std::vector<float> gradients = precomputed_gradients(n, volume);
        gradients_ = Texture::create_3d(n, n, n, TexelFormat::RGB32F, gradients.data());
        // A transfer function with colour and opacity that both change: opaque from 0.2 up, in steps.
        std::vector<float> tf;
        const int entries = 64;
        for (int i = 0; i < entries; ++i) {
            const float x = (i + 0.5f) / entries;
            tf.insert(tf.end(), {x, 0.5f + 0.5f * std::sin(6.0f * x), 1.0f - x, std::clamp((x - 0.2f) * 1.5f, 0.0f, 1.0f)});
        }
        tf_ = Texture::create_2d(entries, 1, TexelFormat::RGBA32F, tf.data());
    }

    const Context& context() const { return *context_; }

    Rendered render(const ShaderProgram& program, const Settings& s) const {
        target_.bind();
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS);  // gl_FragDepth is written as it is, whatever was there
        glClearColor(9.0f, 9.0f, 9.0f, 9.0f);  // no pixel may keep it
        glClearDepth(0.5);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        program.use();
        entry_.bind(0);
        exit_.bind(1);
        volume_.bind(2);
        tf_.bind(3);
        gradients_.bind(4);
        program.set("uEntryPoints", 0);
        program.set("uExitPoints", 1);
        program.set("uVolume", 2);
        program.set("uTransferFunction", 3);
        program.set("uGradientVolume", 4);
        program.set("uStepSize", s.step);
        program.set("uReferenceStepSize", s.reference > 0 ? s.reference : s.step);
        program.set("uEarlyRayThreshold", s.threshold);
        program.set("uIsoValue", s.iso);
        program.set("uBackground", s.background);
        program.set("uVoxelSpacing", glm::vec3(1.0f));
        program.set("uLightPosition", glm::vec3(1.5f, 2.0f, -1.5f));
        program.set("uCameraPosition", glm::vec3(0.5f, 0.5f, -2.0f));
        program.set("uAmbient", 0.2f);
        program.set("uDiffuse", 0.7f);
        program.set("uSpecular", 0.4f);
        program.set("uShininess", 16.0f);
        // Texture coordinates [0, 1]^3 onto clip space [-1, 1]^3: the depth written is z itself.
        glm::mat4 to_clip(1.0f);
        for (int a = 0; a < 3; ++a) {
            to_clip[a][a] = 2.0f;
            to_clip[3][a] = -1.0f;
        }
        program.set("uTextureToClip", to_clip);
        for (const auto& [name, value] : s.modes) program.set(name, value);
        quad_.draw();
        Rendered out;
        out.width = target_.width();
        out.height = target_.height();
        out.depth.resize(static_cast<std::size_t>(out.width) * out.height);
        glReadPixels(0, 0, out.width, out.height, GL_DEPTH_COMPONENT, GL_FLOAT, out.depth.data());
        glDisable(GL_DEPTH_TEST);
        out.color = target_.read_rgba32f();
        check_gl_error("rendering a raycast test image");
        return out;
    }

private:
    std::unique_ptr<Context> context_;
    GpuMesh quad_;
    Framebuffer target_;
    Texture entry_, exit_, volume_, gradients_, tf_;
};

float max_difference(const ImageF& a, const ImageF& b) {
    REQUIRE(a.rgba.size() == b.rgba.size());
    float worst = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) worst = std::max(worst, std::abs(a.rgba[i] - b.rgba[i]));
    return worst;
}

bool all_finite(const Rendered& r) {
    return std::all_of(r.color.rgba.begin(), r.color.rgba.end(), [](float x) { return std::isfinite(x); }) &&
           std::all_of(r.depth.begin(), r.depth.end(), [](float x) { return std::isfinite(x); });
}

// A smooth blob on a gentle ramp, values in [0, 1]: gradients in every direction, empty space around it.
float blob(int i, int j, int k) {
    const glm::vec3 p = (glm::vec3(i, j, k) + 0.5f) / 16.0f - glm::vec3(0.45f, 0.55f, 0.5f);
    return std::clamp(std::exp(-glm::dot(p, p) / 0.06f) + 0.1f * (i / 15.0f), 0.0f, 1.0f);
}

}  // namespace

TEST_CASE("raycast_config: names print and parse, and a bad name is one line naming it and the known ones", "[unit][raycast]") {
    for (G g : {G::None, G::Forward, G::Central, G::Precomputed}) CHECK(parse_gradient(kModules, name_of(kModules, g)) == g);
    for (C c : {C::Raw, C::TransferFunction}) CHECK(parse_classification(kModules, name_of(kModules, c)) == c);
    for (S s : {S::None, S::Phong}) CHECK(parse_shading(kModules, name_of(kModules, s)) == s);
    for (K k : {K::Dvr, K::Mip, K::Isosurface, K::FirstHit}) CHECK(parse_compositing(kModules, name_of(kModules, k)) == k);
    CHECK_THROWS_WITH(parse_gradient(kModules, "centre"), "unknown raycast gradient 'centre' (known: none, forward, central, precomputed)");
    CHECK_THROWS_WITH(parse_classification(kModules, ""), "unknown raycast classification '' (known: raw, tf)");
    CHECK_THROWS_WITH(parse_shading(kModules, "Phong"), "unknown raycast shading 'Phong' (known: none, phong)");
    std::string known;  // the table's rows, dvr, mip, iso, fhp first
    for (const std::string& name : compositing_names(kModules)) known += (known.empty() ? "" : ", ") + name;
    CHECK(known.rfind("dvr, mip, iso, fhp", 0) == 0);
    CHECK_THROWS_WITH(parse_compositing(kModules, "max"), "unknown raycast compositing 'max' (known: " + known + ")");
    CHECK(describe(kModules, make_config(K::Dvr, G::Central, C::TransferFunction, S::Phong)) ==
          "compositing dvr, gradient central, classification tf, shading phong, early termination on");
}

TEST_CASE("raycast_config: Phong without a gradient is refused in one line, and 14 configurations a compositing mode remain", "[unit][raycast]") {
    const std::string refusal = "raycast shading 'phong' needs a gradient for its normal, and gradient is 'none' "
                                "(pick forward, central or precomputed, or shading none)";
    for (K k : {K::Dvr, K::Mip, K::Isosurface, K::FirstHit}) {
        const Config bad = make_config(k, G::None, C::Raw, S::Phong);
        CHECK_THROWS_WITH(validate(kModules, bad), refusal);
        CHECK_THROWS_WITH(generate_raycast_header(kModules, bad), refusal);
        CHECK_THROWS_WITH(raycast_uber_uniforms(kModules, bad), refusal);
    }
    const std::vector<Config> configs = all_raycast_configs(kModules);
    // 4 gradients x 2 classifications x 2 shadings, less Phong without a gradient, for each row of the compositing
    // table (4 of them: 56): a new mode's row brings its 14.
    CHECK(compositing_names(kModules).size() >= 4);
    CHECK(configs.size() == compositing_names(kModules).size() * (4 * 2 * 2 - 2));
    std::set<std::string> distinct;
    for (const Config& c : configs) {
        CHECK_NOTHROW(validate(kModules, c));
        distinct.insert(describe(kModules, c));
    }
    CHECK(distinct.size() == configs.size());
}

TEST_CASE("raycast_config: a module the compositing cannot use is dropped, and the header says so", "[unit][raycast]") {
    // MIP and first hit use neither gradient nor shading, whatever was asked.
    for (K k : {K::Mip, K::FirstHit}) {
        const Config e = effective_config(kModules, make_config(k, G::Central, C::TransferFunction, S::Phong));
        CHECK(e == make_config(k, G::None, C::TransferFunction, S::None, false));
    }
    // DVR and isosurface take the gradient only to shade.
    CHECK(effective_config(kModules, make_config(K::Dvr, G::Forward)) == make_config(K::Dvr));
    CHECK(effective_config(kModules, make_config(K::Isosurface, G::Central, C::Raw, S::Phong)) ==
          make_config(K::Isosurface, G::Central, C::Raw, S::Phong, false));
    CHECK(effective_config(kModules, make_config(K::Dvr, G::Central, C::Raw, S::Phong, false)) ==
          make_config(K::Dvr, G::Central, C::Raw, S::Phong, false));

    CHECK(generate_raycast_header(kModules, make_config(K::Dvr, G::Central, C::TransferFunction, S::Phong)) ==
          "// rc_config.glsl, generated by gsv::generate_raycast_header for: compositing dvr, gradient central, "
          "classification tf, shading phong, early termination on\n"
          "#include \"gradient_central.glsl\"\n"
          "#define RC_GRADIENT(p) rcGradientCentral(p)\n"
          "#include \"classify_tf.glsl\"\n"
          "#define RC_CLASSIFY(intensity) rcClassifyTf(intensity)\n"
          "#include \"shade_phong.glsl\"\n"
          "#define RC_SHADE(color, gradient, p) rcShadePhong(color, gradient, p)\n"
          "#include \"composite_dvr.glsl\"\n"
          "#define RC_START(ray) rcStartDvr(ray)\n"
          "#define RC_COMPOSITE(state, ray, t, intensity) rcCompositeDvr(state, ray, t, intensity)\n"
          "#define RC_TERMINATE(state) rcTerminateDvr(state)\n"
          "#define RC_FINISH(state) rcFinishDvr(state)\n");
    CHECK(generate_raycast_header(kModules, make_config(K::Mip, G::Central, C::Raw, S::Phong)) ==
          "// rc_config.glsl, generated by gsv::generate_raycast_header for: compositing mip, gradient none, "
          "classification raw, shading none, early termination off\n"
          "// (requested: compositing mip, gradient central, classification raw, shading phong, early termination on)\n"
          "#define RC_GRADIENT(p) vec3(0.0)\n"
          "#include \"classify_raw.glsl\"\n"
          "#define RC_CLASSIFY(intensity) rcClassifyRaw(intensity)\n"
          "#define RC_SHADE(color, gradient, p) (color)\n"
          "#include \"composite_mip.glsl\"\n"
          "#define RC_START(ray) rcStartMip(ray)\n"
          "#define RC_COMPOSITE(state, ray, t, intensity) rcCompositeMip(state, ray, t, intensity)\n"
          "#define RC_TERMINATE(state) rcTerminateMip(state)\n"
          "#define RC_FINISH(state) rcFinishMip(state)\n");
    CHECK(generate_raycast_header(kModules, make_config(K::Dvr, G::None, C::Raw, S::None, false))
              .find("#define RC_TERMINATE(state) false\n") != std::string::npos);
    CHECK(raycast_config_file(kModules, make_config(K::Dvr)).name == "rc_config.glsl");

    const std::vector<std::pair<std::string, int>> modes = {{"uGradientMode", 0}, {"uClassificationMode", 1},
                                                            {"uShadingMode", 0},  {"uCompositingMode", 1},
                                                            {"uEarlyTermination", 0}};
    CHECK(raycast_uber_uniforms(kModules, make_config(K::Mip, G::Central, C::TransferFunction, S::Phong)) == modes);
}

namespace {

// What a module table promises for its compositing row i, as one line a broken promise (none: kept): its GLSL file,
// found in `dirs`, defines the four functions its placeholders expand to; its name is the choice, parses back and has
// its phrase in the help; its legend says something or says it has none; it is among the configurations every test
// and sweep runs (the agreement test's loop); and the uber-shader has its file and a branch of its own in every
// placeholder, the last row alone being the fallback (no mode falls through to another's).
std::vector<std::string> compositing_row_problems(const RaycastModules& modules, std::size_t i, const std::vector<fs::path>& dirs) {
    std::vector<std::string> problems;
    const std::vector<std::string> names = compositing_names(modules);
    const K mode = static_cast<K>(i);
    const std::string name = names.at(i);
    if (parse_compositing(modules, name) != mode || name_of(modules, mode) != name) problems.push_back("its name does not parse back");
    const CompositingModule& row = modules.compositings().at(i);
    if (compositing_help(modules).find(name + ": " + row.description) == std::string::npos) problems.push_back("not in the help");
    // Its file, as the generated header includes it, and the function suffix the placeholders expand to.
    const std::string header = generate_raycast_header(modules, make_config(mode));
    const std::size_t include = header.rfind("#include \"");
    const std::size_t start = header.find("#define RC_START(ray) rcStart");
    if (include == std::string::npos || start == std::string::npos) return {"the header includes no compositing file:\n" + header};
    const std::string file = header.substr(include + 10, header.find('"', include + 10) - include - 10);
    const std::string x = header.substr(start + 29, header.find('(', start + 29) - start - 29);
    const auto found = std::find_if(dirs.begin(), dirs.end(), [&](const fs::path& dir) { return fs::is_regular_file(dir / file); });
    if (found == dirs.end()) {
        problems.push_back(file + " is in none of the shader folders");
    } else {
        const std::string glsl = test::read_text(*found / file);
        for (const std::string& function : {"RcState rcStart" + x + "(", "void rcComposite" + x + "(", "bool rcTerminate" + x + "(",
                                            "vec4 rcFinish" + x + "("})
            if (glsl.find(function) == std::string::npos) problems.push_back(file + " does not define " + function + "...)");
    }
    const CompositingLegend legend = compositing_legend(modules, mode);
    if (legend.shown != (std::string(legend.note) != "")) problems.push_back("its legend is shown without a note, or the other way round");
    const std::vector<Config> configs = all_raycast_configs(modules);
    if (std::count_if(configs.begin(), configs.end(), [&](const Config& c) { return c.compositing == mode; }) != 4 * 2 * 2 - 2)
        problems.push_back("not among the configurations tests and sweeps run, 14 a mode");
    const std::string uber = generate_raycast_uber_header(modules);
    if (uber.find("#include \"" + file + "\"") == std::string::npos) problems.push_back("the uber-shader does not include " + file);
    for (const std::string function : {"rcStart", "rcComposite", "rcTerminate", "rcFinish"})
        if (uber.find(function + x + "(") == std::string::npos) problems.push_back("the uber-shader does not call " + function + x);
    const bool branch = uber.find("uCompositingMode == " + std::to_string(i) + ")") != std::string::npos;
    if (branch != (i + 1 < names.size()))
        problems.push_back(branch ? "the last row has a condition, so a value past the table draws nothing"
                                  : "no branch of its own in the uber-shader: it would draw the last row's picture");
    return problems;
}

std::string lines(const std::vector<std::string>& problems) {
    std::string text;
    for (const auto& p : problems) text += p + "\n";
    return text;
}

}  // namespace

TEST_CASE("raycast: every compositing mode has its file, its four functions, a legend, its configurations and an uber-shader branch", "[unit][raycast]") {
    // What lab 06's module table (solutions/lab06_raycasting/raycast_modules.cpp) promises for each row.
    const std::vector<std::string> names = compositing_names(kModules);
    REQUIRE(names.size() >= 4);
    for (std::size_t i = 0; i < names.size(); ++i) {
        INFO(names[i]);
        const std::vector<std::string> problems = compositing_row_problems(kModules, i, {kRaycast});
        INFO(lines(problems));
        CHECK(problems.empty());
    }
}

TEST_CASE("raycast: a compositing mode is a GLSL file and one table row, and its choice, help, error, legend, configurations and both shaders follow", "[unit][raycast]") {
    const RaycastModules extended = kModules.with_compositing(kAverageRow);
    const std::size_t n = kModules.compositings().size();
    const std::vector<std::string> names = compositing_names(extended);
    REQUIRE(names.size() == n + 1);
    CHECK(names.back() == "avg");
    for (std::size_t i = 0; i <= n; ++i) {
        INFO(names[i]);
        const std::vector<std::string> problems = compositing_row_problems(extended, i, {kRaycast, kTestShaders});
        INFO(lines(problems));
        CHECK(problems.empty());
    }
    // The parameter a processor declares from the table: its choices, its help (--help, `list`, the panel) and the
    // error for a name it does not know.
    Params p;
    p.add_choice("compositing", "dvr", compositing_names(extended), compositing_help(extended));
    CHECK_NOTHROW(p.set("compositing", "avg"));
    CHECK(p.get_choice("compositing") == "avg");
    CHECK(p.describe().find("avg: mean intensity, opaque") != std::string::npos);
    CHECK_THROWS_WITH(p.set("compositing", "sum"), Catch::Contains(", fhp, avg"));
    CHECK_THROWS_WITH(parse_compositing(extended, "sum"), Catch::Contains(", fhp, avg)"));
    const K avg = parse_compositing(extended, "avg");
    CHECK(static_cast<std::size_t>(avg) == n);
    CHECK(std::string(compositing_legend(extended, avg).note) == kAverageRow.legend.note);
    // Not shaded: neither gradient nor shading is compiled in, and its termination is its own.
    CHECK(effective_config(extended, make_config(avg, G::Central, C::TransferFunction, S::Phong)) ==
          make_config(avg, G::None, C::TransferFunction, S::None, false));
    CHECK(generate_raycast_header(extended, make_config(avg)).find("#include \"composite_test_avg.glsl\"\n"
                                                                   "#define RC_START(ray) rcStartTestAvg(ray)\n") != std::string::npos);
    // The configurations tests and sweeps run gain its 14; the uber-shader's last branch is its, and the row that was
    // last (first hit) has a condition now.
    CHECK(all_raycast_configs(extended).size() == all_raycast_configs(kModules).size() + 14);
    const std::string uber = generate_raycast_uber_header(extended);
    CHECK(uber.find("    if (uCompositingMode == " + std::to_string(n - 1) + ") return rcFinishFhp(s);\n"
                    "    return rcFinishTestAvg(s);\n") != std::string::npos);
    CHECK(uber.find("uniform int uCompositingMode;     // 0 dvr, 1 mip, 2 iso, 3 fhp, 4 avg\n") != std::string::npos);
}

TEST_CASE("raycast: a compositing row that lacks a piece is refused in one line when the table is made", "[unit][raycast]") {
    const auto lacking = [](auto change) {
        CompositingModule row = kAverageRow;
        change(row);
        return row;
    };
    const std::string row4 = "raycast compositing row 4 ('avg') ";
    // No file or no function: the header, the uber-shader's #include and its branch would have nothing to name.
    CHECK_THROWS_WITH(kModules.with_compositing(lacking([](CompositingModule& r) { r.file = ""; })), row4 + "has no GLSL file");
    CHECK_THROWS_WITH(kModules.with_compositing(lacking([](CompositingModule& r) { r.function = nullptr; })), row4 + "has no function");
    CHECK_THROWS_WITH(kModules.with_compositing(lacking([](CompositingModule& r) { r.name = ""; })),
                      "raycast compositing row 4 ('') has no name");
    CHECK_THROWS_WITH(kModules.with_compositing(lacking([](CompositingModule& r) { r.name = "mip"; })),
                      "raycast compositing row 4 ('mip') has the name of an earlier row");
    // No description: the help would leave it out.
    CHECK_THROWS_WITH(kModules.with_compositing(lacking([](CompositingModule& r) { r.description = ""; })),
                      row4 + "has no description for the parameter's help");
    // The legend's former default (another mode's note for any mode it did not know): a row says its own, or shows none.
    CHECK_THROWS_WITH(kModules.with_compositing(lacking([](CompositingModule& r) { r.legend.note = nullptr; })),
                      row4 + "shows a legend that says nothing (no note)");
    CHECK_THROWS_WITH(kModules.with_compositing(lacking([](CompositingModule& r) { r.legend.shown = false; })),
                      row4 + "has a legend note but shows no legend");
    // A compositing enumerator without its row, and a gradient table short of its enum.
    std::vector<CompositingModule> three(kModules.compositings().begin(), kModules.compositings().begin() + 3);
    CHECK_THROWS_WITH(RaycastModules(kModules.gradients(), kModules.classifications(), kModules.shadings(), three),
                      "the raycast compositing table has 3 rows; RaycastConfig names 4 and more may follow");
    std::vector<RaycastModule> gradients = kModules.gradients();
    gradients.pop_back();
    CHECK_THROWS_WITH(RaycastModules(gradients, kModules.classifications(), kModules.shadings(), kModules.compositings()),
                      "the raycast gradient table has 3 rows; RaycastConfig names 4");
    gradients = kModules.gradients();
    gradients[0].file = "gradient_forward.glsl";
    CHECK_THROWS_WITH(RaycastModules(gradients, kModules.classifications(), kModules.shadings(), kModules.compositings()),
                      "raycast gradient row 0 ('none') leaves the module out, so it names no file and no function");
}

TEST_CASE("raycast: a mode whose GLSL file is missing, or lacks one of its four functions, fails the row check", "[unit][raycast]") {
    test::TempDir dir;
    std::string glsl = test::read_text(kTestShaders / "composite_test_avg.glsl");
    const std::size_t finish = glsl.find("vec4 rcFinishTestAvg(");
    REQUIRE(finish != std::string::npos);
    glsl.resize(finish);
    dir.write("composite_test_partial.glsl", glsl);
    CompositingModule partial = kAverageRow;
    partial.file = "composite_test_partial.glsl";
    const RaycastModules extended = kModules.with_compositing(partial);
    const std::size_t row = kModules.compositings().size();
    CHECK(compositing_row_problems(extended, row, {kRaycast, dir.path()}) ==
          std::vector<std::string>{"composite_test_partial.glsl does not define vec4 rcFinishTestAvg(...)"});
    CHECK(compositing_row_problems(extended, row, {kRaycast}) ==
          std::vector<std::string>{"composite_test_partial.glsl is in none of the shader folders"});
}

TEST_CASE("raycast: each configuration's preprocessed source holds exactly the modules it uses", "[unit][raycast]") {
    for (const Config& config : configs_with_termination_off()) {
        PreprocessOptions options = shader_options();
        options.generated = {raycast_config_file(kModules, config)};
        const ShaderSource source = preprocess_shader(kRaycast / "raycast.frag", options);
        const Config effective = effective_config(kModules, config);
        INFO(describe(kModules, config));
        for (const ModuleFunction& f : module_functions()) {
            INFO(f.name);
            CHECK((source.text.find(f.name) != std::string::npos) == f.chosen(effective));
        }
        CHECK(std::find(source.files.begin(), source.files.end(), "<generated rc_config.glsl>") != source.files.end());
    }
}

TEST_CASE("raycast: every configuration passes glslangValidator, the front end stricter than Mesa", "[unit][raycast]") {
    // Mesa accepts GLSL that glslang (and so Apple's and AMD's compilers) refuses: a struct field named
    // `length`, for one, which glslang reads as the .length() method.
    bool found = false;
    if (const char* path = std::getenv("PATH")) {
        std::stringstream dirs(path);
        std::string dir;
        while (std::getline(dirs, dir, ':'))
            found = found || (!dir.empty() && fs::is_regular_file(fs::path(dir) / "glslangValidator"));
    }
    if (!found) {
        WARN("glslangValidator is not on PATH; skipping");
        return;
    }
    test::TempDir dir;
    std::vector<std::pair<std::string, std::vector<GeneratedFile>>> shaders = {{"raycast_uber.frag", {raycast_uber_file(kModules)}},
                                                                              {"raycast_dvr_handwritten.frag", {}}};
    for (const Config& config : configs_with_termination_off())
        shaders.push_back({"raycast.frag", {raycast_config_file(kModules, config)}});
    int index = 0;
    for (const auto& [fragment, generated] : shaders) {
        PreprocessOptions options = shader_options();
        options.generated = generated;
        const fs::path file = dir.write("shader" + std::to_string(index++) + ".frag",
                                        preprocess_shader(kRaycast / fragment, options).text);
        const fs::path log = dir.path("glslang.log");
        const int status = std::system(("glslangValidator \"" + file.string() + "\" > \"" + log.string() + "\" 2>&1").c_str());
        INFO(fragment << (generated.empty() ? "" : "\n" + generated[0].text) << "\n" << test::read_text(log));
        CHECK(status == 0);
    }
}

TEST_CASE("raycast: every valid configuration compiles and links on a GL 4.1 core context", "[raycast][gl]") {
    auto context = test::headless_context();
    REQUIRE(context->effective_version() == GlVersion{4, 1});
    const std::vector<Config> configs = configs_with_termination_off();
    CHECK(configs.size() == all_raycast_configs(kModules).size() + 14);  // DVR's 14 again, with early termination off
    for (const Config& config : configs) {
        INFO(describe(kModules, config));
        ShaderProgram program;
        try {
            program = specialised(*context, config);
        } catch (const Error& e) {
            FAIL(e.what());
        }
        CHECK(program.id() != 0);
        REQUIRE(program.compiled_sources().size() == 2);
        CHECK(program.compiled_sources()[1].find(describe(kModules, effective_config(kModules, config))) != std::string::npos);
    }
    CHECK_NOTHROW(build_program(*context, "raycast_uber.frag", {raycast_uber_file(kModules)}));
    CHECK_NOTHROW(build_program(*context, "raycast_dvr_handwritten.frag", {}));
}

TEST_CASE("raycast: every uniform of every program the ray caster builds is set by exactly one module's component", "[raycast][gl]") {
    auto context = test::headless_context();
    Params params;  // what the components declare, as a processor's would hold it
    const RaySetup rays(params);
    const VoxelGeometry voxels;
    const GradientLookup gradients;
    const TransferFunctionLookup classification;
    const PhongShading phong(params);
    const DvrCompositing dvr(params);
    const IsoCompositing iso(params);
    const UberModes modes(kModules);
    const ShaderComponents modules{&rays, &voxels, &gradients, &classification, &phong, &dvr, &iso};
    const auto check = [&](const ShaderProgram& program, ShaderComponents components) {
        const std::vector<std::string> problems = uniform_ownership_problems(program, components);
        std::string lines;
        for (const auto& p : problems) lines += p + "\n";
        INFO(lines);
        CHECK(problems.empty());
        CHECK_FALSE(program.active_uniforms().empty());
    };
    for (const Config& config : configs_with_termination_off()) {
        INFO(describe(kModules, config));
        check(specialised(*context, config), modules);
    }
    ShaderComponents uber = modules;
    uber.push_back(&modes);
    check(build_program(*context, "raycast_uber.frag", {raycast_uber_file(kModules)}), uber);
    check(build_program(*context, "raycast_dvr_handwritten.frag", {}), modules);
    // Without the uber-shader's modes, five of its uniforms have no owner: the check sees what is left out.
    CHECK(uniform_ownership_problems(build_program(*context, "raycast_uber.frag", {raycast_uber_file(kModules)}), modules).size() == 5);
}

TEST_CASE("raycast: MIP compiles no gradient and no shading, DVR with central gradients and Phong exactly those", "[raycast][gl]") {
    auto context = test::headless_context();
    auto has = [](const ShaderProgram& p, const std::string& name) {
        return p.compiled_sources()[1].find(name) != std::string::npos;
    };
    for (G gradient : {G::Forward, G::Central, G::Precomputed}) {
        const ShaderProgram mip = specialised(*context, make_config(K::Mip, gradient, C::Raw, S::Phong));
        INFO(name_of(kModules, gradient));
        for (const char* absent : {"rcGradientForward", "rcGradientCentral", "rcGradientPrecomputed", "rcShadePhong",
                                   "uGradientVolume", "uLightPosition", "rcCompositeDvr", "rcClassifyTf"})
            CHECK_FALSE(has(mip, absent));
        CHECK(has(mip, "rcCompositeMip"));
        CHECK(has(mip, "rcClassifyRaw"));
    }
    const ShaderProgram dvr = specialised(*context, make_config(K::Dvr, G::Central, C::Raw, S::Phong));
    for (const char* present : {"rcGradientCentral", "rcShadePhong", "rcClassifyRaw", "rcCompositeDvr"}) CHECK(has(dvr, present));
    for (const char* absent : {"rcGradientForward", "rcGradientPrecomputed", "rcClassifyTf", "rcCompositeMip",
                               "rcCompositeIso", "rcCompositeFhp", "uGradientMode"})
        CHECK_FALSE(has(dvr, absent));
}

TEST_CASE("raycast: MIP along z is the largest sample of each column", "[raycast][gl]") {
    const int n = 16;
    auto value = [](int i, int j, int k) { return static_cast<float>((i * 7 + j * 13 + k * 29) % 31) / 30.0f; };
    const std::vector<float> volume = make_volume(n, value);
    Scene scene(rays_along_z(n), n, volume);
    const ShaderProgram mip = specialised(scene.context(), make_config(K::Mip));
    // 1/16: samples at voxel centres, so exact; 1/23: between them, against trilinear (here linear in z).
    for (const int samples : {16, 23}) {
        INFO(samples << " samples");
        Settings s;
        s.step = 1.0f / samples;
        const Rendered r = scene.render(mip, s);
        float worst = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                float expected = 0;
                for (int m = 0; m < samples; ++m) {
                    const double u = (m + 0.5) / samples * n - 0.5;
                    const int k0 = static_cast<int>(std::floor(u));
                    const double f = u - k0;
                    const float a = value(i, j, std::clamp(k0, 0, n - 1)), b = value(i, j, std::clamp(k0 + 1, 0, n - 1));
                    expected = std::max(expected, static_cast<float>((1 - f) * a + f * b));
                }
                const float* p = r.pixel(i, j);
                worst = std::max({worst, std::abs(p[3] - expected), std::abs(p[0] - expected)});
            }
        // Hardware may round interpolation weights to 8 bits (support/volume/volume.h): 1/512 of a neighbour difference.
        CHECK(worst <= (samples == n ? 1e-6f : 1.0f / 256));
        CHECK(all_finite(r));
    }
}

TEST_CASE("raycast: DVR of a constant volume is the closed form 1 - (1 - a) to the n", "[raycast][gl]") {
    const int n = 16;
    const float a = 0.3f;
    Scene scene(rays_along_z(n), n, make_volume(n, [&](int, int, int) { return a; }));
    const ShaderProgram dvr = specialised(scene.context(), make_config(K::Dvr));
    for (const int samples : {10, 16, 40}) {
        Settings s;
        s.step = 1.0f / samples;  // and no opacity correction: each sample's alpha is a
        const Rendered r = scene.render(dvr, s);
        const float expected = 1.0f - static_cast<float>(std::pow(1.0 - a, samples));
        INFO(samples << " samples, expected " << expected);
        float worst_color = 0, worst_depth = 0;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const float* p = r.pixel(x, y);
                // White, premultiplied: red equals alpha.
                worst_color = std::max({worst_color, std::abs(p[3] - expected), std::abs(p[0] - expected)});
                worst_depth = std::max(worst_depth, std::abs(r.depth_at(x, y) - 0.5f / samples));  // the first sample
            }
        CHECK(worst_color <= 1e-5f);
        CHECK(worst_depth <= 1e-5f);
    }
}

TEST_CASE("raycast: isosurface and first hit depths are the known crossings", "[raycast][gl]") {
    const int n = 16;
    // v = z: trilinear interpolation reproduces it exactly between the first and last voxel centres.
    Scene scene(rays_along_z(n), n, make_volume(n, [&](int, int, int k) { return (k + 0.5f) / n; }));
    const ShaderProgram iso = specialised(scene.context(), make_config(K::Isosurface));
    for (const float iso_value : {0.4f, 0.40625f, 0.7f}) {
        for (const int samples : {2, 7, 16, 20}) {
            INFO("iso " << iso_value << ", " << samples << " samples");
            Settings s;
            s.step = 1.0f / samples;
            s.iso = iso_value;
            const Rendered r = scene.render(iso, s);
            float worst_depth = 0;
            bool opaque_white = true;  // unshaded
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    worst_depth = std::max(worst_depth, std::abs(r.depth_at(x, y) - iso_value));
                    const float* p = r.pixel(x, y);
                    opaque_white = opaque_white && p[0] == 1.0f && p[1] == 1.0f && p[2] == 1.0f && p[3] == 1.0f;
                }
            CHECK(worst_depth <= 5e-4f);
            CHECK(opaque_white);
        }
    }
    // First hit: raw classification makes every sample of v > 0 visible, so the first sample is the hit,
    // and its colour is its position.
    const ShaderProgram fhp = specialised(scene.context(), make_config(K::FirstHit));
    Settings s;
    s.step = 1.0f / 8;
    const Rendered r = scene.render(fhp, s);
    float worst = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float* p = r.pixel(x, y);
            const float expected[] = {(x + 0.5f) / n, (y + 0.5f) / n, 1.0f / 16, 1.0f};
            for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(p[c] - expected[c]));
            worst = std::max(worst, std::abs(r.depth_at(x, y) - 1.0f / 16));
        }
    CHECK(worst <= 1e-5f);
}

TEST_CASE("raycast: entry equal to exit everywhere gives the background and no NaN", "[raycast][gl]") {
    const int n = 16;
    const Rays same = make_rays(n, n, [](float u, float v, glm::vec4& entry, glm::vec4& exit) {
        entry = exit = {u, v, 0.5f, 1.0f};
    });
    Settings s;
    s.background = {0.1f, 0.2f, 0.3f, 1.0f};
    s.threshold = 0.95f;
    auto only_background = [&](const Rendered& r) {
        bool ok = all_finite(r);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const float* p = r.pixel(x, y);
                ok = ok && p[0] == 0.1f && p[1] == 0.2f && p[2] == 0.3f && p[3] == 1.0f && r.depth_at(x, y) == 1.0f;
            }
        return ok;
    };
    {
        Scene scene(same, n, make_volume(n, blob));
        for (const Config& config : all_raycast_configs(kModules)) {
            INFO(describe(kModules, config));
            CHECK(only_background(scene.render(specialised(scene.context(), config), s)));
        }
    }
    // Where the proxy does not cover the pixel (alpha 0), the same.
    Scene missed(make_rays(n, n, [](float, float, glm::vec4&, glm::vec4&) {}), n, make_volume(n, blob));
    for (K k : {K::Dvr, K::Mip, K::Isosurface, K::FirstHit}) {
        INFO(name_of(kModules, k));
        CHECK(only_background(missed.render(specialised(missed.context(), make_config(k)), s)));
    }
}

TEST_CASE("raycast: a constant volume with gradients and Phong gives no NaN, only ambient light", "[raycast][gl]") {
    const int n = 16;
    const float value = 0.6f;
    Scene scene(oblique_rays(), n, make_volume(n, [&](int, int, int) { return value; }));
    for (G gradient : {G::Forward, G::Central, G::Precomputed})
        for (C classification : {C::Raw, C::TransferFunction})
            for (K compositing : {K::Dvr, K::Isosurface}) {
                const Config config = make_config(compositing, gradient, classification, S::Phong);
                INFO(describe(kModules, config));
                Settings s;
                s.iso = 0.5f;
                const Rendered r = scene.render(specialised(scene.context(), config), s);
                REQUIRE(all_finite(r));
                if (classification != C::Raw) continue;
                // A zero gradient is a zero normal: white times the ambient 0.2, no diffuse, no highlight.
                const float* p = r.pixel(12, 10);
                CHECK(p[0] == Approx(0.2f * (compositing == K::Dvr ? p[3] : 1.0f)).margin(1e-5));
                CHECK(p[3] > 0.5f);
            }
}

TEST_CASE("raycast: the isosurface is finite where the volume equals the iso value, the 0 over 0 case", "[raycast][gl]") {
    const int n = 16;
    const float iso = 0.5f;
    // Everywhere, and in the half z >= 0.5 with 0.25 in front of it.
    for (const bool half : {false, true}) {
        INFO((half ? "half" : "whole") << " volume at the iso value");
        Scene scene(rays_along_z(n), n, make_volume(n, [&](int, int, int k) { return !half || k >= n / 2 ? iso : 0.25f; }));
        for (G gradient : {G::Forward, G::Central, G::Precomputed}) {
            Settings s;
            s.iso = iso;
            const Rendered r = scene.render(specialised(scene.context(), make_config(K::Isosurface, gradient, C::Raw, S::Phong)), s);
            REQUIRE(all_finite(r));
            // Whole: the first sample is already on it. Half: interpolation reaches 0.5 at the plateau's
            // first voxel centre, 8.5 / 16, which is a sample.
            CHECK(r.depth_at(3, 4) == Approx(half ? 8.5f / 16 : 0.5f / 16).margin(1e-4));
            CHECK(r.pixel(3, 4)[3] == 1.0f);
        }
    }
}

TEST_CASE("raycast: opacity correction keeps DVR the same when the step halves, and without it the image changes", "[raycast][gl]") {
    const int n = 16;
    Scene scene(oblique_rays(), n, make_volume(n, [](int, int, int) { return 0.02f; }));
    const ShaderProgram dvr = specialised(scene.context(), make_config(K::Dvr));
    auto render = [&](float step, float reference) {
        Settings s;
        s.step = step;
        s.reference = reference;
        return scene.render(dvr, s).color;
    };
    const float step = 1.0f / 40;
    const float corrected = max_difference(render(step, step), render(step / 2, step));
    const float uncorrected = max_difference(render(step, step), render(step / 2, step / 2));
    INFO("corrected " << corrected << ", uncorrected " << uncorrected);
    CHECK(corrected <= 1.0f / 255);
    CHECK(uncorrected > 0.1f);  // twice the samples at the same opacity: much more opaque
}

TEST_CASE("raycast: early termination at 0.95 changes alpha by at most 0.05", "[raycast][gl]") {
    const int n = 16;
    Scene scene(oblique_rays(), n, make_volume(n, [](int, int, int) { return 0.2f; }));
    Settings all_the_way, early;
    all_the_way.step = early.step = 1.0f / 64;
    early.threshold = 0.95f;
    const ShaderProgram dvr = specialised(scene.context(), make_config(K::Dvr));
    const ImageF full = scene.render(dvr, all_the_way).color;
    const ImageF stopped = scene.render(dvr, early).color;
    float worst = 0;
    for (std::size_t i = 3; i < full.rgba.size(); i += 4) worst = std::max(worst, std::abs(full.rgba[i] - stopped.rgba[i]));
    CHECK(worst <= 0.05f);
    CHECK(worst > 0.0f);  // it did stop early
    // Compiled without it, the threshold changes nothing.
    const ShaderProgram never = specialised(scene.context(), make_config(K::Dvr, G::None, C::Raw, S::None, false));
    CHECK(max_difference(scene.render(never, early).color, full) <= 1e-6f);
}

namespace {

// The settings the agreement tests draw with: a step off the voxel grid, opacity correction, early termination.
Settings agreement_settings() {
    Settings s;
    s.step = 1.0f / 37;
    s.reference = 1.0f / 16;
    s.threshold = 0.95f;
    s.iso = 0.45f;
    s.background = {0.1f, 0.1f, 0.2f, 1.0f};
    return s;
}

// The uber-shader generated from `modules`, given each configuration's mode uniforms, draws what that
// configuration's specialised shader draws.
void check_uber_agrees(const Scene& scene, const RaycastModules& modules, const std::vector<Config>& configs) {
    const ShaderProgram uber = build_program(scene.context(), "raycast_uber.frag", {raycast_uber_file(modules)});
    const Settings s = agreement_settings();
    for (const Config& config : configs) {
        INFO(describe(modules, config));
        const Rendered expected = scene.render(specialised(scene.context(), config, modules), s);
        REQUIRE(all_finite(expected));
        // Two blank images would agree too: this one must show something over the background.
        float strongest = 0;
        for (std::size_t i = 0; i < expected.color.rgba.size(); ++i)
            strongest = std::max(strongest, std::abs(expected.color.rgba[i] - s.background[static_cast<int>(i % 4)]));
        CHECK(strongest > 0.2f);
        Settings modes = s;
        modes.modes = raycast_uber_uniforms(modules, config);
        const Rendered got = scene.render(uber, modes);
        CHECK(max_difference(got.color, expected.color) <= 1.0f / 255);
        float depth = 0;
        for (std::size_t i = 0; i < got.depth.size(); ++i) depth = std::max(depth, std::abs(got.depth[i] - expected.depth[i]));
        CHECK(depth <= 1e-5f);
    }
}

}  // namespace

TEST_CASE("raycast: the uber-shader and the hand-written DVR draw what the specialised shader draws", "[raycast][gl]") {
    const int n = 16;
    Scene scene(oblique_rays(), n, make_volume(n, blob));
    check_uber_agrees(scene, kModules, configs_with_termination_off());
    const Settings s = agreement_settings();
    const ShaderProgram handwritten = build_program(scene.context(), "raycast_dvr_handwritten.frag", {});
    for (const bool early : {true, false}) {
        INFO("early termination " << early);
        Settings t = s;
        t.threshold = early ? 0.95f : 1.0f;
        const Rendered expected =
            scene.render(specialised(scene.context(), make_config(K::Dvr, G::Central, C::TransferFunction, S::Phong)), t);
        const Rendered got = scene.render(handwritten, t);
        CHECK(max_difference(got.color, expected.color) <= 1.0f / 255);
        // Not a blank image compared with a blank image: the blob shows.
        float brightest = 0;
        for (std::size_t i = 3; i < expected.color.rgba.size(); i += 4) brightest = std::max(brightest, expected.color.rgba[i]);
        CHECK(brightest > 0.5f);
    }
}

TEST_CASE("raycast: a compositing mode added as a GLSL file and a row compiles, and the uber-shader draws what its specialised shader draws", "[raycast][gl]") {
    // The agreement loop runs over the table it is given: the new mode's configurations are in it, and with no branch
    // of its own the uber-shader would draw another mode's picture here.
    const int n = 16;
    Scene scene(oblique_rays(), n, make_volume(n, blob));
    const RaycastModules extended = kModules.with_compositing(kAverageRow);
    const K avg = parse_compositing(extended, "avg");
    std::vector<Config> configs;
    for (const Config& config : configs_with_termination_off(extended))
        if (config.compositing == avg) configs.push_back(config);
    CHECK(configs.size() == 14);
    check_uber_agrees(scene, extended, configs);
}

TEST_CASE("raycast: a component declares its parameters with the uniforms they feed, and sets them from their values", "[raycast][gl]") {
    auto context = test::headless_context();
    Params params;  // as the ray caster's processor holds them: the lab adopts them, and --set, case and network files set them
    RaySetup rays(params);
    PhongShading phong(params);
    DvrCompositing dvr(params);
    IsoCompositing iso(params);
    // Each parameter declared once, by its component, and its spec names the uniform it feeds (`list` prints it).
    for (const auto& [name, uniform] : std::vector<std::pair<std::string, std::string>>{
             {"ambient", "uAmbient"}, {"diffuse", "uDiffuse"}, {"specular", "uSpecular"}, {"shininess", "uShininess"},
             {"early_ray_threshold", "uEarlyRayThreshold"}, {"iso_value", "uIsoValue"}}) {
        INFO(name);
        CHECK(params.spec(name).uniform == uniform);
        const std::vector<std::string> owned = phong.uniforms(), dvr_owned = dvr.uniforms(), iso_owned = iso.uniforms();
        CHECK(std::count(owned.begin(), owned.end(), uniform) + std::count(dvr_owned.begin(), dvr_owned.end(), uniform) +
                  std::count(iso_owned.begin(), iso_owned.end(), uniform) == 1);
    }
    // One range, one parser: the component's declaration refuses what it always refused.
    CHECK_THROWS_WITH(params.set("ambient", "2"), Catch::Contains("ambient"));
    CHECK_THROWS_WITH(params.set("samples_per_voxel", "0.01"), Catch::Contains("samples_per_voxel"));
    params.set("ambient", "0.375");
    params.set("shininess", "40");
    params.set("iso_value", "0.625");
    params.set("early_ray_threshold", "0.5");
    params.set("samples_per_voxel", "2");

    const ShaderProgram uber = build_program(*context, "raycast_uber.frag", {raycast_uber_file(kModules)});
    uber.use();
    const auto uniform = [&](const std::string& name) {
        float value = -1;
        glGetUniformfv(uber.id(), uber.location(name), &value);
        return value;
    };
    // A texture the drawing code has not pointed the component at is one line naming it, not a draw from unit 0.
    CHECK_THROWS_WITH(rays.apply(uber), "ray setup (the skeleton): uEntryPoints has no texture to bind");
    const float texel[4] = {0, 0, 0, 1};
    const Texture image = Texture::create_2d(1, 1, TexelFormat::RGBA32F, texel);
    const Texture volume = Texture::create_3d(1, 1, 1, TexelFormat::R32F, texel);
    rays.entry_points = rays.exit_points = &image;
    rays.volume = &volume;
    rays.largest_side = 16;
    dvr.voxel_step = 1.0f / 16;
    apply_components(uber, {&rays, &phong, &dvr, &iso});
    check_gl_error("setting the components' uniforms");
    CHECK(uniform("uAmbient") == 0.375f);
    CHECK(uniform("uShininess") == 40.0f);
    CHECK(uniform("uIsoValue") == 0.625f);
    CHECK(uniform("uEarlyRayThreshold") == 0.5f);
    CHECK(uniform("uStepSize") == static_cast<float>(1.0 / (2.0 * 16)));
    CHECK(uniform("uReferenceStepSize") == 1.0f / 16);
    params.set("opacity_correction", "off");  // a reference step of 0: no correction
    dvr.apply(uber);
    CHECK(uniform("uReferenceStepSize") == 0.0f);
}
