#include "common/shader/param_uniforms.h"

#include "common/core/error.h"
#include "common/core/number_text.h"

namespace gsv {
namespace {

bool sets(ParamType type, UniformKind kind) {
    switch (type) {
    case ParamType::Float: return kind == UniformKind::Float;
    case ParamType::Int:
    case ParamType::Bool:
    case ParamType::Choice: return kind == UniformKind::Int || kind == UniformKind::Bool;
    case ParamType::Vec3: return kind == UniformKind::Vec3;
    case ParamType::File:
    case ParamType::Text: return true;  // never a uniform
    }
    return false;
}

const char* kind_name(UniformKind kind) {
    switch (kind) {
    case UniformKind::Float: return "a float";
    case UniformKind::Int: return "an int";
    case UniformKind::Bool: return "a bool";
    case UniformKind::Vec3: return "a vec3";
    case UniformKind::Sampler: return "a sampler";
    case UniformKind::Other: return "a uniform of another type";
    }
    return "?";
}

bool reaches_uniform(const ParamSpec& s) {
    return !s.compile_time && !s.uniform.empty() && s.type != ParamType::File && s.type != ParamType::Text;
}

[[noreturn]] void refuse(const ParamSpec& s, const std::string& program, const std::string& what) {
    throw Error("parameter '" + s.name + "' would set the uniform " + s.uniform + ", which " + program + " declares as " + what +
                ": rename the parameter, or declare it without_uniform() if only the lab reads it");
}

}  // namespace

void check_param_uniforms(const Params& params, const std::vector<UniformDeclaration>& uniforms, const std::string& program) {
    for (const ParamSpec& s : params.specs()) {
        if (!reaches_uniform(s)) continue;
        for (const UniformDeclaration& u : uniforms)
            if (u.name == s.uniform && !sets(s.type, u.kind)) refuse(s, "program '" + program + "'", kind_name(u.kind));
    }
}

std::vector<ShaderDefine> param_defines(const Params& params) {
    std::vector<ShaderDefine> out;
    const std::vector<ParamSpec>& specs = params.specs();
    for (std::size_t i = 0; i < specs.size(); ++i) {
        const ParamSpec& s = specs[i];
        if (!s.compile_time) continue;
        const double number = params.number_at(i);
        switch (s.type) {
        case ParamType::Bool:
            if (number != 0) out.push_back({s.define, "1"});
            break;
        case ParamType::Choice:
            out.push_back({s.define, std::to_string(static_cast<int>(number))});
            out.push_back({s.define + "_" + macro_name_for(params.word_at(i)), "1"});
            break;
        case ParamType::Int: out.push_back({s.define, std::to_string(static_cast<long>(number))}); break;
        case ParamType::Float: out.push_back({s.define, format_number(number, 7)}); break;
        case ParamType::Vec3: out.push_back({s.define, "vec3(" + params.text_at(i) + ")"}); break;
        case ParamType::File:
        case ParamType::Text: break;
        }
    }
    return out;
}

void apply_param_uniforms(const Params& params, const ShaderProgram& program) {
    const std::vector<ParamSpec>& specs = params.specs();
    std::vector<std::size_t> read;
    for (std::size_t i = 0; i < specs.size(); ++i) {
        const ParamSpec& s = specs[i];
        if (s.compile_time) read.push_back(i);
        if (!reaches_uniform(s)) continue;
        // Checked when the program was made; a shader edited since may have turned the uniform into a texture.
        if (program.texture_unit(s.uniform) >= 0) refuse(s, "the program in use", kind_name(UniformKind::Sampler));
        if (program.has(s.uniform)) read.push_back(i);
        switch (s.type) {
        case ParamType::Float: program.set(s.uniform, static_cast<float>(params.number_at(i))); break;
        case ParamType::Int:
        case ParamType::Bool:
        case ParamType::Choice: program.set(s.uniform, static_cast<int>(params.number_at(i))); break;
        case ParamType::Vec3: program.set(s.uniform, params.vec3_at(i)); break;
        case ParamType::File:
        case ParamType::Text: break;
        }
    }
    params.note_reads(read);
}

}  // namespace gsv
