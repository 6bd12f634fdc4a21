#include "common/shader/param_uniforms.h"

#include "common/core/number_text.h"
#include "common/shader/shader_program.h"

namespace gsv {

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
        // A sampler of the same name (lab 02's `input` and its texture uInput) keeps the unit the program gave it.
        const bool sampler = !s.compile_time && program.texture_unit(s.uniform) >= 0;
        if (s.compile_time || (s.type != ParamType::File && s.type != ParamType::Text && !sampler && program.has(s.uniform))) read.push_back(i);
        if (s.compile_time || sampler) continue;
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
