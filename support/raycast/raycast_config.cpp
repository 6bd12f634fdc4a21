#include "support/raycast/raycast_config.h"

#include "common/core/error.h"

namespace gsv {
namespace {

using Config = RaycastConfig;

// One table per placeholder, so names, files and functions cannot drift apart. An empty file: the
// module is left out and its placeholder gets the no-op.
struct Module {
    const char* name;
    const char* file;      // in the lab folder (an include dir), as the generated header includes it
    const char* function;  // what the placeholder expands to
};

const Module kGradients[] = {
    {"none", "", ""},
    {"forward", "gradient_forward.glsl", "rcGradientForward"},
    {"central", "gradient_central.glsl", "rcGradientCentral"},
    {"precomputed", "gradient_precomputed.glsl", "rcGradientPrecomputed"},
};
const Module kClassifications[] = {
    {"raw", "classify_raw.glsl", "rcClassifyRaw"},
    {"tf", "classify_tf.glsl", "rcClassifyTf"},
};
const Module kShadings[] = {
    {"none", "", ""},
    {"phong", "shade_phong.glsl", "rcShadePhong"},
};
// A compositing module has three functions: rcComposite<X>, rcTerminate<X>, rcFinish<X>.
const Module kCompositings[] = {
    {"dvr", "composite_dvr.glsl", "Dvr"},
    {"mip", "composite_mip.glsl", "Mip"},
    {"iso", "composite_iso.glsl", "Iso"},
    {"fhp", "composite_fhp.glsl", "Fhp"},
};

template <class E, std::size_t N>
const Module& module_of(const Module (&table)[N], E value) {
    return table[static_cast<std::size_t>(value)];
}

template <class E, std::size_t N>
E parse(const Module (&table)[N], const char* what, const std::string& name) {
    std::string known;
    for (std::size_t i = 0; i < N; ++i) {
        if (name == table[i].name) return static_cast<E>(i);
        known += std::string(i ? ", " : "") + table[i].name;
    }
    throw Error("unknown raycast " + std::string(what) + " '" + name + "' (known: " + known + ")");
}

bool uses_shading(Config::Compositing compositing) {
    return compositing == Config::Compositing::Dvr || compositing == Config::Compositing::Isosurface;
}

}  // namespace

bool operator==(const RaycastConfig& a, const RaycastConfig& b) {
    return a.gradient == b.gradient && a.classification == b.classification && a.shading == b.shading &&
           a.compositing == b.compositing && a.early_termination == b.early_termination;
}

const char* name_of(Config::Gradient v) { return module_of(kGradients, v).name; }
const char* name_of(Config::Classification v) { return module_of(kClassifications, v).name; }
const char* name_of(Config::Shading v) { return module_of(kShadings, v).name; }
const char* name_of(Config::Compositing v) { return module_of(kCompositings, v).name; }

Config::Gradient parse_gradient(const std::string& name) { return parse<Config::Gradient>(kGradients, "gradient", name); }
Config::Classification parse_classification(const std::string& name) {
    return parse<Config::Classification>(kClassifications, "classification", name);
}
Config::Shading parse_shading(const std::string& name) { return parse<Config::Shading>(kShadings, "shading", name); }
Config::Compositing parse_compositing(const std::string& name) {
    return parse<Config::Compositing>(kCompositings, "compositing", name);
}

std::string describe(const RaycastConfig& c) {
    return std::string("compositing ") + name_of(c.compositing) + ", gradient " + name_of(c.gradient) +
           ", classification " + name_of(c.classification) + ", shading " + name_of(c.shading) +
           ", early termination " + (c.early_termination ? "on" : "off");
}

void validate(const RaycastConfig& c) {
    if (c.shading == Config::Shading::Phong && c.gradient == Config::Gradient::None)
        throw Error("raycast shading 'phong' needs a gradient for its normal, and gradient is 'none' "
                    "(pick forward, central or precomputed, or shading none)");
}

RaycastConfig effective_config(const RaycastConfig& c) {
    RaycastConfig e = c;
    if (!uses_shading(c.compositing)) e.shading = Config::Shading::None;
    if (e.shading == Config::Shading::None) e.gradient = Config::Gradient::None;
    if (c.compositing != Config::Compositing::Dvr) e.early_termination = false;
    return e;
}

std::vector<RaycastConfig> all_raycast_configs() {
    std::vector<RaycastConfig> configs;
    for (int composite = 0; composite < 4; ++composite)
        for (int gradient = 0; gradient < 4; ++gradient)
            for (int classify = 0; classify < 2; ++classify)
                for (int shade = 0; shade < 2; ++shade) {
                    RaycastConfig c;
                    c.compositing = static_cast<Config::Compositing>(composite);
                    c.gradient = static_cast<Config::Gradient>(gradient);
                    c.classification = static_cast<Config::Classification>(classify);
                    c.shading = static_cast<Config::Shading>(shade);
                    if (c.shading == Config::Shading::Phong && c.gradient == Config::Gradient::None) continue;
                    configs.push_back(c);
                }
    return configs;
}

std::string generate_raycast_header(const RaycastConfig& requested) {
    validate(requested);
    const RaycastConfig c = effective_config(requested);
    std::string text = "// " + std::string(kRaycastConfigFile) + ", generated by gsv::generate_raycast_header for: " +
                       describe(c) + "\n";
    if (c != requested) text += "// (requested: " + describe(requested) + ")\n";
    auto include = [&](const Module& m) {
        if (*m.file) text += std::string("#include \"") + m.file + "\"\n";
    };
    // The placeholders the compositing module calls must be defined before its text, so it comes last.
    const Module& gradient = module_of(kGradients, c.gradient);
    include(gradient);
    text += *gradient.function ? std::string("#define RC_GRADIENT(p) ") + gradient.function + "(p)\n"
                               : "#define RC_GRADIENT(p) vec3(0.0)\n";
    const Module& classification = module_of(kClassifications, c.classification);
    include(classification);
    text += std::string("#define RC_CLASSIFY(intensity) ") + classification.function + "(intensity)\n";
    const Module& shading = module_of(kShadings, c.shading);
    include(shading);
    text += *shading.function ? std::string("#define RC_SHADE(color, gradient, p) ") + shading.function +
                                    "(color, gradient, p)\n"
                              : "#define RC_SHADE(color, gradient, p) (color)\n";
    const Module& compositing = module_of(kCompositings, c.compositing);
    const std::string x = compositing.function;
    include(compositing);
    text += "#define RC_START(ray) rcStart" + x + "(ray)\n";
    text += "#define RC_COMPOSITE(state, ray, t, intensity) rcComposite" + x + "(state, ray, t, intensity)\n";
    // Only DVR's termination is optional; the others' is their algorithm (stop at the hit, or never).
    const bool terminates = c.compositing != Config::Compositing::Dvr || c.early_termination;
    text += terminates ? "#define RC_TERMINATE(state) rcTerminate" + x + "(state)\n"
                       : std::string("#define RC_TERMINATE(state) false\n");
    text += "#define RC_FINISH(state) rcFinish" + x + "(state)\n";
    return text;
}

GeneratedFile raycast_config_file(const RaycastConfig& config) {
    return {kRaycastConfigFile, generate_raycast_header(config)};
}

std::vector<std::pair<std::string, int>> raycast_uber_uniforms(const RaycastConfig& requested) {
    validate(requested);
    const RaycastConfig c = effective_config(requested);
    return {{"uGradientMode", static_cast<int>(c.gradient)},
            {"uClassificationMode", static_cast<int>(c.classification)},
            {"uShadingMode", static_cast<int>(c.shading)},
            {"uCompositingMode", static_cast<int>(c.compositing)},
            {"uEarlyTermination", c.early_termination ? 1 : 0}};
}

}  // namespace gsv
