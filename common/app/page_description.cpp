#include "common/app/page_description.h"

#include "common/params/params.h"

namespace gsv {
namespace {

const char* kind_name(ParamType type) {
    switch (type) {
    case ParamType::Float: return "float";
    case ParamType::Int: return "int";
    case ParamType::Bool: return "bool";
    case ParamType::Choice: return "choice";
    case ParamType::Vec3: return "vec3";
    case ParamType::File: return "file";
    case ParamType::Text: return "text";
    }
    return "unknown";
}

Json strings(const std::vector<std::string>& values) {
    Json out = Json::array();
    for (const auto& v : values) out.push_back(v);
    return out;
}

}  // namespace

Json describe_params(const Params& params) {
    Json out = Json::array();
    for (const ParamSpec& spec : params.specs()) {
        Json p = Json::object();
        p["name"] = spec.name;
        p["kind"] = kind_name(spec.type);
        p["help"] = spec.help;
        if (spec.type == ParamType::Float || spec.type == ParamType::Int || spec.type == ParamType::Vec3) {
            p["min"] = spec.min;
            p["max"] = spec.max;
            // The window's arrow-key step; a slider moves in finer steps than that for floats.
            p["step"] = spec.step > 0 ? spec.step : spec.type == ParamType::Int ? 1.0 : (spec.max - spec.min) / 50;
        }
        // A Bool (and an effect) is a Choice of off and on on the command line and in cases.
        if (spec.type == ParamType::Choice) p["choices"] = strings(spec.choices);
        p["compile_time"] = spec.compile_time;
        p["effect"] = spec.effect;
        p["animated"] = spec.animation_axis;
        p["knob"] = !spec.sweep_values.empty();
        p["same_picture"] = spec.same_picture_why;
        p["value"] = params.text_at(&spec - params.specs().data());
        out.push_back(p);
    }
    return out;
}

Json param_states(const Params& params) {
    Json out = Json::array();
    for (const ParamSpec& spec : params.specs()) {
        Json p = Json::object();
        p["name"] = spec.name;
        p["value"] = params.text_at(&spec - params.specs().data());
        p["inactive"] = params.inactive_reason(spec.name);
        out.push_back(p);
    }
    return out;
}

Json describe_cases(const std::vector<RenderCase>& cases) {
    Json out = Json::array();
    for (const RenderCase& c : cases) {
        Json j = Json::object();
        j["name"] = c.name;
        j["description"] = c.description;
        j["settings"] = strings(c.settings);
        j["todo"] = c.todo;
        out.push_back(j);
    }
    return out;
}

}  // namespace gsv
