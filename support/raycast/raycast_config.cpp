#include "support/raycast/raycast_config.h"

#include "common/core/error.h"

#include <set>

namespace gsv {
namespace {

using Config = RaycastConfig;

bool given(const char* text) { return text && *text; }

// Checks one table: every row named, names distinct, and a file and a function together. `left_out` rows (the
// placeholder's no-op) have neither; every other row has both. Missing columns become "", so nothing below reads
// a null.
template <class Row>
void check_table(std::vector<Row>& rows, const char* what, std::size_t size, bool exact, std::size_t left_out_rows) {
    auto refuse = [&](std::size_t i, const std::string& problem) {
        throw Error(std::string("raycast ") + what + " row " + std::to_string(i) + " ('" + (given(rows[i].name) ? rows[i].name : "") +
                    "') " + problem);
    };
    if (exact ? rows.size() != size : rows.size() < size)
        throw Error(std::string("the raycast ") + what + " table has " + std::to_string(rows.size()) + " rows; RaycastConfig names " +
                    std::to_string(size) + (exact ? "" : " and more may follow"));
    std::set<std::string> names;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        Row& row = rows[i];
        if (!given(row.name)) refuse(i, "has no name");
        if (!names.insert(row.name).second) refuse(i, "has the name of an earlier row");
        const bool left_out = i < left_out_rows;
        if (left_out && (given(row.file) || given(row.function))) refuse(i, "leaves the module out, so it names no file and no function");
        if (!left_out && !given(row.file)) refuse(i, "has no GLSL file");
        if (!left_out && !given(row.function)) refuse(i, "has no function");
        if (!row.file) row.file = "";
        if (!row.function) row.function = "";
    }
}

// An enumerator with no row is a mistake in the caller's table: one line rather than a read past it.
template <class Row, class E>
const Row& module_of(const std::vector<Row>& table, E value) {
    const auto i = static_cast<std::size_t>(value);
    if (i >= table.size()) throw Error("raycast module " + std::to_string(i) + " has no row in its table");
    return table[i];
}

template <class E, class Row>
E parse(const std::vector<Row>& table, const char* what, const std::string& name) {
    std::string known;
    for (std::size_t i = 0; i < table.size(); ++i) {
        if (name == table[i].name) return static_cast<E>(i);
        known += std::string(i ? ", " : "") + table[i].name;
    }
    throw Error("unknown raycast " + std::string(what) + " '" + name + "' (known: " + known + ")");
}

template <class Row>
std::vector<std::string> names_of(const std::vector<Row>& table) {
    std::vector<std::string> names;
    for (const Row& m : table) names.push_back(m.name);
    return names;
}

}  // namespace

RaycastModules::RaycastModules(std::vector<RaycastModule> gradients, std::vector<RaycastModule> classifications,
                               std::vector<RaycastModule> shadings, std::vector<CompositingModule> compositings)
    : gradients_(std::move(gradients)), classifications_(std::move(classifications)), shadings_(std::move(shadings)),
      compositings_(std::move(compositings)) {
    // Row 0 of the gradients and the shadings is Gradient::None and Shading::None: the module left out.
    check_table(gradients_, "gradient", 4, true, 1);
    check_table(classifications_, "classification", 2, true, 0);
    check_table(shadings_, "shading", 2, true, 1);
    check_table(compositings_, "compositing", 4, false, 0);
    for (std::size_t i = 0; i < compositings_.size(); ++i) {
        CompositingModule& row = compositings_[i];
        const std::string which = "raycast compositing row " + std::to_string(i) + " ('" + row.name + "') ";
        if (!given(row.description)) throw Error(which + "has no description for the parameter's help");
        if (row.legend.shown && !given(row.legend.note)) throw Error(which + "shows a legend that says nothing (no note)");
        if (!row.legend.shown && given(row.legend.note)) throw Error(which + "has a legend note but shows no legend");
        if (!row.legend.note) row.legend.note = "";
    }
}

RaycastModules RaycastModules::with_compositing(const CompositingModule& row) const {
    std::vector<CompositingModule> compositings = compositings_;
    compositings.push_back(row);
    return RaycastModules(gradients_, classifications_, shadings_, std::move(compositings));
}

bool operator==(const RaycastConfig& a, const RaycastConfig& b) {
    return a.gradient == b.gradient && a.classification == b.classification && a.shading == b.shading &&
           a.compositing == b.compositing && a.early_termination == b.early_termination;
}

const char* name_of(const RaycastModules& m, Config::Gradient v) { return module_of(m.gradients(), v).name; }
const char* name_of(const RaycastModules& m, Config::Classification v) { return module_of(m.classifications(), v).name; }
const char* name_of(const RaycastModules& m, Config::Shading v) { return module_of(m.shadings(), v).name; }
const char* name_of(const RaycastModules& m, Config::Compositing v) { return module_of(m.compositings(), v).name; }

std::vector<std::string> gradient_names(const RaycastModules& m) { return names_of(m.gradients()); }
std::vector<std::string> classification_names(const RaycastModules& m) { return names_of(m.classifications()); }
std::vector<std::string> shading_names(const RaycastModules& m) { return names_of(m.shadings()); }
std::vector<std::string> compositing_names(const RaycastModules& m) { return names_of(m.compositings()); }

std::string compositing_help(const RaycastModules& m) {
    std::string help;
    for (const CompositingModule& row : m.compositings())
        help += (help.empty() ? "" : ", ") + std::string(row.name) + ": " + row.description;
    return help;
}

Config::Gradient parse_gradient(const RaycastModules& m, const std::string& name) {
    return parse<Config::Gradient>(m.gradients(), "gradient", name);
}
Config::Classification parse_classification(const RaycastModules& m, const std::string& name) {
    return parse<Config::Classification>(m.classifications(), "classification", name);
}
Config::Shading parse_shading(const RaycastModules& m, const std::string& name) {
    return parse<Config::Shading>(m.shadings(), "shading", name);
}
Config::Compositing parse_compositing(const RaycastModules& m, const std::string& name) {
    return parse<Config::Compositing>(m.compositings(), "compositing", name);
}

std::string describe(const RaycastModules& m, const RaycastConfig& c) {
    return std::string("compositing ") + name_of(m, c.compositing) + ", gradient " + name_of(m, c.gradient) +
           ", classification " + name_of(m, c.classification) + ", shading " + name_of(m, c.shading) +
           ", early termination " + (c.early_termination ? "on" : "off");
}

void validate(const RaycastModules& m, const RaycastConfig& c) {
    if (c.shading == Config::Shading::None || c.gradient != Config::Gradient::None) return;
    // "forward, central or precomputed": the gradients there are.
    std::string pick;
    const auto& gradients = m.gradients();
    for (std::size_t i = 1; i < gradients.size(); ++i)
        pick += std::string(i == 1 ? "" : i + 1 == gradients.size() ? " or " : ", ") + gradients[i].name;
    throw Error("raycast shading '" + std::string(name_of(m, c.shading)) + "' needs a gradient for its normal, and gradient is '" +
                name_of(m, c.gradient) + "' (pick " + pick + ", or shading " + name_of(m, Config::Shading::None) + ")");
}

RaycastConfig effective_config(const RaycastModules& m, const RaycastConfig& c) {
    RaycastConfig e = c;
    const CompositingModule& compositing = module_of(m.compositings(), c.compositing);
    if (!compositing.shaded) e.shading = Config::Shading::None;
    if (e.shading == Config::Shading::None) e.gradient = Config::Gradient::None;
    if (!compositing.optional_termination) e.early_termination = false;
    return e;
}

CompositingLegend compositing_legend(const RaycastModules& m, Config::Compositing compositing) {
    return module_of(m.compositings(), compositing).legend;
}

std::vector<RaycastConfig> all_raycast_configs(const RaycastModules& m) {
    std::vector<RaycastConfig> configs;
    for (std::size_t composite = 0; composite < m.compositings().size(); ++composite)
        for (std::size_t gradient = 0; gradient < m.gradients().size(); ++gradient)
            for (std::size_t classify = 0; classify < m.classifications().size(); ++classify)
                for (std::size_t shade = 0; shade < m.shadings().size(); ++shade) {
                    RaycastConfig c;
                    c.compositing = static_cast<Config::Compositing>(composite);
                    c.gradient = static_cast<Config::Gradient>(gradient);
                    c.classification = static_cast<Config::Classification>(classify);
                    c.shading = static_cast<Config::Shading>(shade);
                    if (c.shading != Config::Shading::None && c.gradient == Config::Gradient::None) continue;
                    configs.push_back(c);
                }
    return configs;
}

std::string generate_raycast_header(const RaycastModules& m, const RaycastConfig& requested) {
    validate(m, requested);
    const RaycastConfig c = effective_config(m, requested);
    std::string text = "// " + std::string(kRaycastConfigFile) + ", generated by gsv::generate_raycast_header for: " +
                       describe(m, c) + "\n";
    if (c != requested) text += "// (requested: " + describe(m, requested) + ")\n";
    auto include = [&](const RaycastModule& row) {
        if (*row.file) text += std::string("#include \"") + row.file + "\"\n";
    };
    // The placeholders the compositing module calls must be defined before its text, so it comes last.
    const RaycastModule& gradient = module_of(m.gradients(), c.gradient);
    include(gradient);
    text += *gradient.function ? std::string("#define RC_GRADIENT(p) ") + gradient.function + "(p)\n"
                               : "#define RC_GRADIENT(p) vec3(0.0)\n";
    const RaycastModule& classification = module_of(m.classifications(), c.classification);
    include(classification);
    text += std::string("#define RC_CLASSIFY(intensity) ") + classification.function + "(intensity)\n";
    const RaycastModule& shading = module_of(m.shadings(), c.shading);
    include(shading);
    text += *shading.function ? std::string("#define RC_SHADE(color, gradient, p) ") + shading.function +
                                    "(color, gradient, p)\n"
                              : "#define RC_SHADE(color, gradient, p) (color)\n";
    const CompositingModule& compositing = module_of(m.compositings(), c.compositing);
    const std::string x = compositing.function;
    include(compositing);
    text += "#define RC_START(ray) rcStart" + x + "(ray)\n";
    text += "#define RC_COMPOSITE(state, ray, t, intensity) rcComposite" + x + "(state, ray, t, intensity)\n";
    // Only an optional termination (DVR's) can be left out; the others' is their algorithm (stop at the hit, or never).
    const bool terminates = !compositing.optional_termination || c.early_termination;
    text += terminates ? "#define RC_TERMINATE(state) rcTerminate" + x + "(state)\n"
                       : std::string("#define RC_TERMINATE(state) false\n");
    text += "#define RC_FINISH(state) rcFinish" + x + "(state)\n";
    return text;
}

GeneratedFile raycast_config_file(const RaycastModules& m, const RaycastConfig& config) {
    return {kRaycastConfigFile, generate_raycast_header(m, config)};
}

namespace {

// "0 none, 1 forward, 2 central, 3 precomputed": what a mode uniform's values mean.
template <class Row>
std::string value_names(const std::vector<Row>& table) {
    std::string out;
    for (std::size_t i = 0; i < table.size(); ++i) out += (i ? ", " : "") + std::to_string(i) + " " + table[i].name;
    return out;
}

// A function that calls the row the mode uniform names; rows without a function (the module left out) and any
// value past the table give `none`, where there is one, else the last row does.
std::string dispatch(const std::vector<RaycastModule>& table, const std::string& signature, const std::string& uniform,
                     const std::string& args, const std::string& none) {
    std::string text = signature + " {\n";
    for (std::size_t i = 0; i < table.size(); ++i) {
        if (!*table[i].function) continue;
        const std::string call = std::string(table[i].function) + "(" + args + ")";
        const bool last = none.empty() && i + 1 == table.size();
        text += last ? "    return " + call + ";\n" : "    if (" + uniform + " == " + std::to_string(i) + ") return " + call + ";\n";
    }
    if (!none.empty()) text += "    return " + none + ";\n";
    return text + "}\n";
}

}  // namespace

std::string generate_raycast_uber_header(const RaycastModules& m) {
    std::string text = "// " + std::string(kRaycastUberFile) + ", generated by gsv::generate_raycast_uber_header: every module, "
                       "chosen per draw by uniforms\n";
    auto include_all = [&](const auto& table) {
        for (const auto& row : table)
            if (*row.file) text += std::string("#include \"") + row.file + "\"\n";
    };
    include_all(m.gradients());
    include_all(m.classifications());
    include_all(m.shadings());
    text += "\n// The values are the order of gsv::RaycastConfig's enumerators, the tables' rows.\n";
    text += "uniform int uGradientMode;        // " + value_names(m.gradients()) + "\n";
    text += "uniform int uClassificationMode;  // " + value_names(m.classifications()) + "\n";
    text += "uniform int uShadingMode;         // " + value_names(m.shadings()) + "\n";
    text += "uniform int uCompositingMode;     // " + value_names(m.compositings()) + "\n";
    text += "uniform int uEarlyTermination;    // where termination is a setting: 0 runs every ray to its exit\n\n";
    text += dispatch(m.gradients(), "vec3 rcGradientUber(vec3 p)", "uGradientMode", "p", "vec3(0.0)");
    text += dispatch(m.classifications(), "vec4 rcClassifyUber(float intensity)", "uClassificationMode", "intensity", "");
    text += dispatch(m.shadings(), "vec3 rcShadeUber(vec3 color, vec3 gradient, vec3 p)", "uShadingMode", "color, gradient, p", "color");
    text += "\n#define RC_GRADIENT(p) rcGradientUber(p)\n"
            "#define RC_CLASSIFY(intensity) rcClassifyUber(intensity)\n"
            "#define RC_SHADE(color, gradient, p) rcShadeUber(color, gradient, p)\n\n";
    // The compositing modules call the placeholders above, so they come after them.
    const std::vector<CompositingModule>& compositings = m.compositings();
    include_all(compositings);
    const std::size_t n = compositings.size();
    auto each = [&](const std::string& signature, const auto& line) {
        text += "\n" + signature + " {\n";
        for (std::size_t i = 0; i < n; ++i) {
            const std::string condition = "uCompositingMode == " + std::to_string(i);
            text += line(compositings[i], i + 1 == n ? std::string() : condition);
        }
        text += "}\n";
    };
    each("RcState rcStartUber(RcRay ray)", [](const CompositingModule& row, const std::string& when) {
        return (when.empty() ? "    return " : "    if (" + when + ") return ") + std::string("rcStart") + row.function + "(ray);\n";
    });
    bool first = true;
    each("void rcCompositeUber(inout RcState s, RcRay ray, float t, float intensity)", [&](const CompositingModule& row, const std::string& when) {
        const std::string call = std::string("rcComposite") + row.function + "(s, ray, t, intensity);\n";
        const std::string head = when.empty() ? "    else " : (first ? "    if (" : "    else if (") + when + ") ";
        first = false;
        return head + call;
    });
    each("bool rcTerminateUber(RcState s)", [](const CompositingModule& row, const std::string& when) {
        const std::string call = (row.optional_termination ? std::string("uEarlyTermination != 0 && ") : std::string()) +
                                 "rcTerminate" + row.function + "(s);\n";
        return (when.empty() ? "    return " : "    if (" + when + ") return ") + call;
    });
    each("vec4 rcFinishUber(RcState s)", [](const CompositingModule& row, const std::string& when) {
        return (when.empty() ? "    return " : "    if (" + when + ") return ") + std::string("rcFinish") + row.function + "(s);\n";
    });
    text += "\n#define RC_START(ray) rcStartUber(ray)\n"
            "#define RC_COMPOSITE(state, ray, t, intensity) rcCompositeUber(state, ray, t, intensity)\n"
            "#define RC_TERMINATE(state) rcTerminateUber(state)\n"
            "#define RC_FINISH(state) rcFinishUber(state)\n";
    return text;
}

GeneratedFile raycast_uber_file(const RaycastModules& m) { return {kRaycastUberFile, generate_raycast_uber_header(m)}; }

std::vector<std::pair<std::string, int>> raycast_uber_uniforms(const RaycastModules& m, const RaycastConfig& requested) {
    validate(m, requested);
    const RaycastConfig c = effective_config(m, requested);
    return {{"uGradientMode", static_cast<int>(c.gradient)},
            {"uClassificationMode", static_cast<int>(c.classification)},
            {"uShadingMode", static_cast<int>(c.shading)},
            {"uCompositingMode", static_cast<int>(c.compositing)},
            {"uEarlyTermination", c.early_termination ? 1 : 0}};
}

}  // namespace gsv
