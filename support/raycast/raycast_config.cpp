#include "support/raycast/raycast_config.h"

#include "common/core/error.h"

#include <iterator>

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
// A compositing module has four functions: rcStart<X>, rcComposite<X>, rcTerminate<X>, rcFinish<X>. Each row also
// says what the mode uses and what its legend says, so a new mode is its GLSL file and a row here: the
// choices, the configurations the tests run, the uber-shader and the legend all follow from the table.
struct CompositingModule : Module {
    bool shaded;                // uses the gradient and the shading (else neither is compiled in)
    bool optional_termination;  // early termination is a setting (DVR's); else it is the algorithm itself
    CompositingLegend legend;
};
const CompositingModule kCompositings[] = {
    {{"dvr", "composite_dvr.glsl", "Dvr"}, true, true,
     {true, "Opacity per voxel-long step; each sample is blended front to back.", false}},
    {{"mip", "composite_mip.glsl", "Mip"}, false, false,
     {true, "MIP: each pixel shows the largest intensity on its ray, its colour times its opacity.", false}},
    {{"iso", "composite_iso.glsl", "Iso"}, true, false,
     {true, "Isosurface: the colour at the iso value, shaded, opaque.", true}},
    {{"fhp", "composite_fhp.glsl", "Fhp"}, false, false, {false, "", false}},  // its colours are positions
};

// An enumerator with no row is a mistake in this file: one line rather than a read past the table.
template <class Row, class E, std::size_t N>
const Row& module_of(const Row (&table)[N], E value) {
    const auto i = static_cast<std::size_t>(value);
    if (i >= N) throw Error("raycast module " + std::to_string(i) + " has no row in its table (raycast_config.cpp)");
    return table[i];
}

template <class E, class Row, std::size_t N>
E parse(const Row (&table)[N], const char* what, const std::string& name) {
    std::string known;
    for (std::size_t i = 0; i < N; ++i) {
        if (name == table[i].name) return static_cast<E>(i);
        known += std::string(i ? ", " : "") + table[i].name;
    }
    throw Error("unknown raycast " + std::string(what) + " '" + name + "' (known: " + known + ")");
}

template <class Row, std::size_t N>
std::vector<std::string> names_of(const Row (&table)[N]) {
    std::vector<std::string> names;
    for (const Row& m : table) names.push_back(m.name);
    return names;
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

std::vector<std::string> gradient_names() { return names_of(kGradients); }
std::vector<std::string> classification_names() { return names_of(kClassifications); }
std::vector<std::string> shading_names() { return names_of(kShadings); }
std::vector<std::string> compositing_names() { return names_of(kCompositings); }

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
    const CompositingModule& compositing = module_of(kCompositings, c.compositing);
    if (!compositing.shaded) e.shading = Config::Shading::None;
    if (e.shading == Config::Shading::None) e.gradient = Config::Gradient::None;
    if (!compositing.optional_termination) e.early_termination = false;
    return e;
}

CompositingLegend compositing_legend(Config::Compositing compositing) { return module_of(kCompositings, compositing).legend; }

std::vector<RaycastConfig> all_raycast_configs() {
    std::vector<RaycastConfig> configs;
    for (std::size_t composite = 0; composite < std::size(kCompositings); ++composite)
        for (std::size_t gradient = 0; gradient < std::size(kGradients); ++gradient)
            for (std::size_t classify = 0; classify < std::size(kClassifications); ++classify)
                for (std::size_t shade = 0; shade < std::size(kShadings); ++shade) {
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
    const CompositingModule& compositing = module_of(kCompositings, c.compositing);
    const std::string x = compositing.function;
    include(compositing);
    text += "#define RC_START(ray) rcStart" + x + "(ray)\n";
    text += "#define RC_COMPOSITE(state, ray, t, intensity) rcComposite" + x + "(state, ray, t, intensity)\n";
    // Only DVR's termination is optional; the others' is their algorithm (stop at the hit, or never).
    const bool terminates = !compositing.optional_termination || c.early_termination;
    text += terminates ? "#define RC_TERMINATE(state) rcTerminate" + x + "(state)\n"
                       : std::string("#define RC_TERMINATE(state) false\n");
    text += "#define RC_FINISH(state) rcFinish" + x + "(state)\n";
    return text;
}

GeneratedFile raycast_config_file(const RaycastConfig& config) {
    return {kRaycastConfigFile, generate_raycast_header(config)};
}

namespace {

// "0 none, 1 forward, 2 central, 3 precomputed": what a mode uniform's values mean.
template <class Row, std::size_t N>
std::string value_names(const Row (&table)[N]) {
    std::string out;
    for (std::size_t i = 0; i < N; ++i) out += (i ? ", " : "") + std::to_string(i) + " " + table[i].name;
    return out;
}

// A function that calls the row the mode uniform names; rows without a function (the module left out) and any
// value past the table give `none`, where there is one, else the last row does.
template <class Row, std::size_t N>
std::string dispatch(const Row (&table)[N], const std::string& signature, const std::string& uniform, const std::string& args,
                     const std::string& none) {
    std::string text = signature + " {\n";
    for (std::size_t i = 0; i < N; ++i) {
        if (!*table[i].function) continue;
        const std::string call = std::string(table[i].function) + "(" + args + ")";
        const bool last = none.empty() && i + 1 == N;
        text += last ? "    return " + call + ";\n" : "    if (" + uniform + " == " + std::to_string(i) + ") return " + call + ";\n";
    }
    if (!none.empty()) text += "    return " + none + ";\n";
    return text + "}\n";
}

}  // namespace

std::string generate_raycast_uber_header() {
    std::string text = "// " + std::string(kRaycastUberFile) + ", generated by gsv::generate_raycast_uber_header: every module, "
                       "chosen per draw by uniforms\n";
    auto include_all = [&](const auto& table) {
        for (const auto& m : table)
            if (*m.file) text += std::string("#include \"") + m.file + "\"\n";
    };
    include_all(kGradients);
    include_all(kClassifications);
    include_all(kShadings);
    text += "\n// The values are the order of gsv::RaycastConfig's enumerators, the tables' rows.\n";
    text += "uniform int uGradientMode;        // " + value_names(kGradients) + "\n";
    text += "uniform int uClassificationMode;  // " + value_names(kClassifications) + "\n";
    text += "uniform int uShadingMode;         // " + value_names(kShadings) + "\n";
    text += "uniform int uCompositingMode;     // " + value_names(kCompositings) + "\n";
    text += "uniform int uEarlyTermination;    // where termination is a setting: 0 runs every ray to its exit\n\n";
    text += dispatch(kGradients, "vec3 rcGradientUber(vec3 p)", "uGradientMode", "p", "vec3(0.0)");
    text += dispatch(kClassifications, "vec4 rcClassifyUber(float intensity)", "uClassificationMode", "intensity", "");
    text += dispatch(kShadings, "vec3 rcShadeUber(vec3 color, vec3 gradient, vec3 p)", "uShadingMode", "color, gradient, p", "color");
    text += "\n#define RC_GRADIENT(p) rcGradientUber(p)\n"
            "#define RC_CLASSIFY(intensity) rcClassifyUber(intensity)\n"
            "#define RC_SHADE(color, gradient, p) rcShadeUber(color, gradient, p)\n\n";
    // The compositing modules call the placeholders above, so they come after them.
    include_all(kCompositings);
    const std::size_t n = std::size(kCompositings);
    auto each = [&](const std::string& signature, const auto& line) {
        text += "\n" + signature + " {\n";
        for (std::size_t i = 0; i < n; ++i) {
            const std::string condition = "uCompositingMode == " + std::to_string(i);
            text += line(kCompositings[i], i + 1 == n ? std::string() : condition);
        }
        text += "}\n";
    };
    each("RcState rcStartUber(RcRay ray)", [](const CompositingModule& m, const std::string& when) {
        return (when.empty() ? "    return " : "    if (" + when + ") return ") + std::string("rcStart") + m.function + "(ray);\n";
    });
    bool first = true;
    each("void rcCompositeUber(inout RcState s, RcRay ray, float t, float intensity)", [&](const CompositingModule& m, const std::string& when) {
        const std::string call = std::string("rcComposite") + m.function + "(s, ray, t, intensity);\n";
        const std::string head = when.empty() ? "    else " : (first ? "    if (" : "    else if (") + when + ") ";
        first = false;
        return head + call;
    });
    each("bool rcTerminateUber(RcState s)", [](const CompositingModule& m, const std::string& when) {
        const std::string call = (m.optional_termination ? std::string("uEarlyTermination != 0 && ") : std::string()) +
                                 "rcTerminate" + m.function + "(s);\n";
        return (when.empty() ? "    return " : "    if (" + when + ") return ") + call;
    });
    each("vec4 rcFinishUber(RcState s)", [](const CompositingModule& m, const std::string& when) {
        return (when.empty() ? "    return " : "    if (" + when + ") return ") + std::string("rcFinish") + m.function + "(s);\n";
    });
    text += "\n#define RC_START(ray) rcStartUber(ray)\n"
            "#define RC_COMPOSITE(state, ray, t, intensity) rcCompositeUber(state, ray, t, intensity)\n"
            "#define RC_TERMINATE(state) rcTerminateUber(state)\n"
            "#define RC_FINISH(state) rcFinishUber(state)\n";
    return text;
}

GeneratedFile raycast_uber_file() { return {kRaycastUberFile, generate_raycast_uber_header()}; }

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
