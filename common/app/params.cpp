#include "common/app/params.h"

#include "common/core/error.h"
#include "common/core/number_text.h"
#include "common/shader/shader_program.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace gsv {
namespace {

std::string uniform_name_for(const std::string& name) {
    std::string out = "u";
    bool upper = true;
    for (char c : name) {
        if (c == '_' || c == '-') {
            upper = true;
            continue;
        }
        out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
        upper = false;
    }
    return out;
}

std::string macro_name_for(const std::string& name) {
    std::string out;
    for (char c : name) out += (c == '-') ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

double parse_number(const std::string& name, const std::string& text) {
    const std::optional<double> v = parse_finite_number(text);
    if (!v) throw Error("parameter '" + name + "' = '" + text + "' is not a number");
    return *v;
}

std::string range_text(const ParamSpec& s) {
    return "[" + format_number(s.min, 7) + ", " + format_number(s.max, 7) + "]";
}

}  // namespace

ParamSpec& ParamSpec::at_compile_time(std::string macro) {
    compile_time = true;
    define = macro.empty() ? macro_name_for(name) : std::move(macro);
    return *this;
}

ParamSpec& ParamSpec::applies_when(std::string param, std::vector<std::string> values) {
    applies_when_all.push_back({std::move(param), std::move(values)});
    return *this;
}

ParamSpec& ParamSpec::accuracy_knob(std::vector<std::string> values) {
    sweep_values = std::move(values);
    return *this;
}

ParamSpec& Params::add(ParamSpec spec, Value value) {
    for (const auto& s : specs_)
        if (s.name == spec.name) throw Error("parameter '" + spec.name + "' declared twice");
    spec.uniform = uniform_name_for(spec.name);
    specs_.push_back(std::move(spec));
    values_.push_back(std::move(value));
    return specs_.back();
}

ParamSpec& Params::add_float(const std::string& name, double value, double min, double max, const std::string& help) {
    ParamSpec s;
    s.name = name, s.type = ParamType::Float, s.help = help, s.min = min, s.max = max;
    Value v;
    v.number = value;
    return add(std::move(s), v);
}

ParamSpec& Params::add_int(const std::string& name, int value, int min, int max, const std::string& help) {
    ParamSpec s;
    s.name = name, s.type = ParamType::Int, s.help = help, s.min = min, s.max = max, s.step = 1;
    Value v;
    v.number = value;
    return add(std::move(s), v);
}

ParamSpec& Params::add_bool(const std::string& name, bool value, const std::string& help) {
    ParamSpec s;
    s.name = name, s.type = ParamType::Bool, s.help = help, s.min = 0, s.max = 1;
    Value v;
    v.number = value ? 1 : 0;
    return add(std::move(s), v);
}

ParamSpec& Params::add_choice(const std::string& name, const std::string& value, std::vector<std::string> choices,
                              const std::string& help) {
    ParamSpec s;
    s.name = name, s.type = ParamType::Choice, s.help = help, s.choices = std::move(choices);
    s.max = static_cast<double>(s.choices.size()) - 1;
    Value v;
    v.choice = value;
    auto it = std::find(s.choices.begin(), s.choices.end(), value);
    v.number = static_cast<double>(it - s.choices.begin());
    return add(std::move(s), v);
}

ParamSpec& Params::add_vec3(const std::string& name, glm::vec3 value, double min, double max, const std::string& help) {
    ParamSpec s;
    s.name = name, s.type = ParamType::Vec3, s.help = help, s.min = min, s.max = max;
    Value v;
    v.vec = value;
    return add(std::move(s), v);
}

ParamSpec& Params::add_file(const std::string& name, const std::string& value, const std::string& help) {
    ParamSpec s;
    s.name = name, s.type = ParamType::File, s.help = help;
    Value v;
    v.choice = value;
    return add(std::move(s), v);
}

ParamSpec& Params::add_effect(const std::string& name, bool on, const std::string& help) {
    ParamSpec& s = add_bool(name, on, help);
    s.effect = true;
    return s.at_compile_time("EFFECT_" + macro_name_for(name));
}

std::size_t Params::index_of(const std::string& name) const {
    for (std::size_t i = 0; i < specs_.size(); ++i)
        if (specs_[i].name == name) return i;
    std::string known;
    for (const auto& s : specs_) known += (known.empty() ? "" : ", ") + s.name;
    throw Error("unknown parameter '" + name + "' (this lab has: " + known + ")");
}

std::size_t Params::read_index(const std::string& name) const {
    const std::size_t i = index_of(name);
    if (read_log_.log) read_log_.log->push_back(i);
    return i;
}

std::vector<std::size_t>* Params::swap_read_log(std::vector<std::size_t>* log) const {
    std::vector<std::size_t>* previous = read_log_.log;
    read_log_.log = log;
    return previous;
}

void Params::note_reads(const std::vector<std::size_t>& indices) const {
    if (read_log_.log) read_log_.log->insert(read_log_.log->end(), indices.begin(), indices.end());
}

const ParamSpec& Params::spec(const std::string& name) const { return specs_[index_of(name)]; }

void Params::set(const std::string& name, const std::string& text) {
    const std::size_t i = index_of(name);
    const ParamSpec& s = specs_[i];
    Value& v = values_[i];
    switch (s.type) {
    case ParamType::Float:
    case ParamType::Int: {
        const double x = parse_number(name, text);
        if (s.type == ParamType::Int && x != std::floor(x))
            throw Error("parameter '" + name + "' = " + text + " is not an integer");
        if (x < s.min || x > s.max)
            throw Error("parameter '" + name + "' = " + text + " is out of range " + range_text(s));
        v.number = x;
        break;
    }
    case ParamType::Bool:
        if (text == "1" || text == "true" || text == "on" || text == "yes") v.number = 1;
        else if (text == "0" || text == "false" || text == "off" || text == "no") v.number = 0;
        else throw Error("parameter '" + name + "' = '" + text + "' is not a boolean (use on/off, true/false, 1/0)");
        break;
    case ParamType::Choice: {
        auto it = std::find(s.choices.begin(), s.choices.end(), text);
        if (it == s.choices.end()) {
            std::string list;
            for (const auto& c : s.choices) list += (list.empty() ? "" : ", ") + c;
            throw Error("parameter '" + name + "' = '" + text + "' is not one of: " + list);
        }
        v.choice = text;
        v.number = static_cast<double>(it - s.choices.begin());
        break;
    }
    case ParamType::File:
        if (text.empty()) throw Error("parameter '" + name + "' needs a file path");
        v.choice = text;
        break;
    case ParamType::Vec3: {
        std::string t = text;
        std::replace(t.begin(), t.end(), ';', ',');
        std::vector<std::string> parts;
        std::stringstream ss(t);
        for (std::string part; std::getline(ss, part, ',');) parts.push_back(part);
        if (parts.size() != 3)
            throw Error("parameter '" + name + "' = '" + text + "' needs three comma-separated numbers");
        glm::vec3 out;
        for (int k = 0; k < 3; ++k) {
            const double x = parse_number(name, parts[static_cast<std::size_t>(k)]);
            if (x < s.min || x > s.max)
                throw Error("parameter '" + name + "' = " + text + ": component " + parts[static_cast<std::size_t>(k)] +
                            " is out of range " + range_text(s));
            out[k] = static_cast<float>(x);
        }
        v.vec = out;
        break;
    }
    }
}

void Params::set_assignment(const std::string& assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw Error("bad parameter assignment '" + assignment + "' (expected name=value)");
    set(assignment.substr(0, eq), assignment.substr(eq + 1));
}

std::string Params::get_text(const std::string& name) const { return text_at(read_index(name)); }

std::string Params::text_at(std::size_t i) const {
    const Value& v = values_.at(i);
    switch (specs_[i].type) {
    case ParamType::Float: return format_number(v.number, 7);
    case ParamType::Int: return std::to_string(static_cast<long>(v.number));
    case ParamType::Bool: return v.number != 0 ? "on" : "off";
    case ParamType::Choice:
    case ParamType::File: return v.choice;
    case ParamType::Vec3: return format_number(v.vec.x, 7) + "," + format_number(v.vec.y, 7) + "," + format_number(v.vec.z, 7);
    }
    return "";
}

float Params::get_float(const std::string& name) const { return static_cast<float>(values_[read_index(name)].number); }
int Params::get_int(const std::string& name) const { return static_cast<int>(values_[read_index(name)].number); }
bool Params::get_bool(const std::string& name) const { return values_[read_index(name)].number != 0; }
const std::string& Params::get_choice(const std::string& name) const { return values_[read_index(name)].choice; }
glm::vec3 Params::get_vec3(const std::string& name) const { return values_[read_index(name)].vec; }
const std::string& Params::get_file(const std::string& name) const { return values_[read_index(name)].choice; }

void Params::nudge(const std::string& name, int steps) {
    const std::size_t i = index_of(name);
    const ParamSpec& s = specs_[i];
    Value& v = values_[i];
    switch (s.type) {
    case ParamType::File: break;  // no sensible next file; typed on the command line
    case ParamType::Bool: v.number = v.number != 0 ? 0 : 1; break;
    case ParamType::Choice: {
        const int n = static_cast<int>(s.choices.size());
        const int k = ((static_cast<int>(v.number) + steps) % n + n) % n;
        v.number = k;
        v.choice = s.choices[static_cast<std::size_t>(k)];
        break;
    }
    case ParamType::Float:
    case ParamType::Int: {
        const double step = s.step > 0 ? s.step : (s.max - s.min) / 50.0;
        v.number = std::clamp(v.number + steps * step, s.min, s.max);
        if (s.type == ParamType::Int) v.number = std::round(v.number);
        break;
    }
    case ParamType::Vec3: {
        // Window mode turns a vector (a light position) about the vertical axis: the one move that always reads well.
        const float angle = glm::radians(10.0f * static_cast<float>(steps));
        const glm::vec3 p = v.vec;
        v.vec = glm::clamp(glm::vec3(std::cos(angle) * p.x + std::sin(angle) * p.z, p.y,
                                     -std::sin(angle) * p.x + std::cos(angle) * p.z),
                           glm::vec3(static_cast<float>(s.min)), glm::vec3(static_cast<float>(s.max)));
        break;
    }
    }
}

std::vector<ShaderDefine> Params::defines() const {
    std::vector<ShaderDefine> out;
    for (std::size_t i = 0; i < specs_.size(); ++i) {
        const ParamSpec& s = specs_[i];
        if (!s.compile_time) continue;
        const Value& v = values_[i];
        switch (s.type) {
        case ParamType::Bool:
            if (v.number != 0) out.push_back({s.define, "1"});
            break;
        case ParamType::Choice:
            out.push_back({s.define, std::to_string(static_cast<int>(v.number))});
            out.push_back({s.define + "_" + macro_name_for(v.choice), "1"});
            break;
        case ParamType::Int: out.push_back({s.define, std::to_string(static_cast<long>(v.number))}); break;
        case ParamType::Float: out.push_back({s.define, format_number(v.number, 7)}); break;
        case ParamType::Vec3: out.push_back({s.define, "vec3(" + text_at(i) + ")"}); break;
        case ParamType::File: break;
        }
    }
    return out;
}

void Params::apply_uniforms(const ShaderProgram& program) const {
    for (std::size_t i = 0; i < specs_.size(); ++i) {
        const ParamSpec& s = specs_[i];
        // A sampler of the same name (lab 02's `input` and its texture uInput) keeps the unit the program gave it.
        const bool sampler = !s.compile_time && program.texture_unit(s.uniform) >= 0;
        if (read_log_.log && (s.compile_time || (s.type != ParamType::File && !sampler && program.has(s.uniform))))
            read_log_.log->push_back(i);
        if (s.compile_time || sampler) continue;
        const Value& v = values_[i];
        switch (s.type) {
        case ParamType::Float: program.set(s.uniform, static_cast<float>(v.number)); break;
        case ParamType::Int:
        case ParamType::Bool:
        case ParamType::Choice: program.set(s.uniform, static_cast<int>(v.number)); break;
        case ParamType::Vec3: program.set(s.uniform, v.vec); break;
        case ParamType::File: break;
        }
    }
}

const ParamSpec* Params::knob() const {
    for (const auto& s : specs_)
        if (!s.sweep_values.empty()) return &s;
    return nullptr;
}

const ParamSpec* Params::animation_axis() const {
    for (const auto& s : specs_)
        if (s.animation_axis) return &s;
    return nullptr;
}

const ParamSpec* Params::series() const {
    for (const auto& s : specs_)
        if (s.sweep_series) return &s;
    return nullptr;
}

std::string Params::describe() const {
    std::ostringstream out;
    for (std::size_t i = 0; i < specs_.size(); ++i) {
        const ParamSpec& s = specs_[i];
        out << "  " << s.name << " = " << get_text(s.name) << "  ";
        switch (s.type) {
        case ParamType::Float: out << "float " << range_text(s); break;
        case ParamType::Int: out << "int " << range_text(s); break;
        case ParamType::Bool: out << (s.effect ? "effect on|off" : "bool on|off"); break;
        case ParamType::Choice: {
            out << "one of ";
            for (std::size_t k = 0; k < s.choices.size(); ++k) out << (k ? "|" : "") << s.choices[k];
            break;
        }
        case ParamType::Vec3: out << "x,y,z each in " << range_text(s); break;
        case ParamType::File: out << "file path"; break;
        }
        if (s.type == ParamType::File) out << ", read by the lab";
        else if (s.compile_time) out << ", compiled in as " << s.define;
        else out << ", uniform " << s.uniform;
        if (!s.sweep_values.empty()) out << ", ACCURACY KNOB";
        for (const auto& condition : s.applies_when_all) {
            out << ", only where " << condition.param << "=";
            for (std::size_t k = 0; k < condition.values.size(); ++k) out << (k ? "|" : "") << condition.values[k];
        }
        out << "\n      " << s.help << "\n";
    }
    return out.str();
}

std::string Params::inactive_reason(const std::string& name) const {
    for (const auto& condition : specs_[index_of(name)].applies_when_all) {
        const std::string value = text_at(index_of(condition.param));
        if (std::find(condition.values.begin(), condition.values.end(), value) != condition.values.end()) continue;
        std::string wanted;
        for (std::size_t k = 0; k < condition.values.size(); ++k)
            wanted += (k == 0 ? "" : k + 1 == condition.values.size() ? " or " : ", ") + condition.values[k];
        return "needs " + condition.param + "=" + wanted + " (it is " + value + ")";
    }
    return {};
}

bool Params::applies(const std::string& name) const { return inactive_reason(name).empty(); }

void Params::check_applies(const std::vector<std::string>& names, const std::string& where) const {
    for (const auto& name : names) {
        const std::string reason = inactive_reason(name);
        if (!reason.empty())
            throw Error(where + name + "=" + text_at(index_of(name)) + " has no effect here: it " + reason);
    }
}

}  // namespace gsv
