#include "common/params/params.h"

#include "common/core/error.h"
#include "common/core/number_text.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <utility>

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

double parse_number(const std::string& name, const std::string& text) {
    const std::optional<double> v = parse_finite_number(text);
    if (!v) throw Error("parameter '" + name + "' = '" + text + "' is not a number");
    return *v;
}

std::string range_text(const ParamSpec& s) {
    return "[" + format_number(s.min, 7) + ", " + format_number(s.max, 7) + "]";
}

const char* type_name(ParamType type) {
    switch (type) {
    case ParamType::Float: return "a float";
    case ParamType::Int: return "an int";
    case ParamType::Bool: return "a bool";
    case ParamType::Choice: return "a choice";
    case ParamType::Vec3: return "a vec3";
    case ParamType::File: return "a file path";
    case ParamType::Text: return "a text";
    }
    return "?";
}

}  // namespace

std::string macro_name_for(const std::string& name) {
    std::string out;
    for (char c : name) out += (c == '-') ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

std::size_t Params::add(ParamSpec spec, Value value, bool adopted) {
    // Names end up in `--set name=value`, case files and network files, where '=', '.', '#' and blanks mean something.
    const bool file_safe = !spec.name.empty() && std::all_of(spec.name.begin(), spec.name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
    if (!file_safe) throw Error("parameter name '" + spec.name + "' may only use letters, digits, '_' and '-'");
    spec.scope = scope_;
    spec.owner = owner_;
    for (const auto& s : specs_)
        if (s.name == spec.name)
            throw Error("parameter '" + spec.name + "' declared twice" +
                        (s.owner.empty() && spec.owner.empty() ? std::string() : " (by " + (s.owner.empty() ? "the lab" : s.owner) +
                                                                                 " and " + (spec.owner.empty() ? "the lab" : spec.owner) + ")"));
    if (!adopted) spec.uniform = uniform_name_for(spec.name);  // an adopted one keeps its declarer's (or none)
    if (spec.type != ParamType::File && spec.type != ParamType::Text) check_uniform_free(spec.name, npos, spec.uniform);
    specs_.push_back(std::move(spec));
    values_.push_back(std::move(value));
    return specs_.size() - 1;
}

Param<float> Params::add_float(const std::string& name, double value, double min, double max, const std::string& help) {
    ParamSpec s;
    s.name = name, s.type = ParamType::Float, s.help = help, s.min = min, s.max = max;
    Value v;
    v.number = value;
    return Param<float>(this, add(std::move(s), v));
}

Param<int> Params::add_int(const std::string& name, int value, int min, int max, const std::string& help) {
    ParamSpec s;
    s.name = name, s.type = ParamType::Int, s.help = help, s.min = min, s.max = max, s.step = 1;
    Value v;
    v.number = value;
    return Param<int>(this, add(std::move(s), v));
}

Param<bool> Params::add_bool(const std::string& name, bool value, const std::string& help) {
    ParamSpec s;
    s.name = name, s.type = ParamType::Bool, s.help = help, s.min = 0, s.max = 1;
    Value v;
    v.number = value ? 1 : 0;
    return Param<bool>(this, add(std::move(s), v));
}

Param<std::string> Params::add_choice(const std::string& name, const std::string& value, std::vector<std::string> choices,
                                      const std::string& help) {
    ParamSpec s;
    s.name = name, s.type = ParamType::Choice, s.help = help, s.choices = std::move(choices);
    s.max = static_cast<double>(s.choices.size()) - 1;
    auto it = std::find(s.choices.begin(), s.choices.end(), value);
    if (it == s.choices.end()) throw Error("parameter '" + name + "' defaults to '" + value + "', which is not one of its choices");
    Value v;
    v.word = value;
    v.number = static_cast<double>(it - s.choices.begin());
    return Param<std::string>(this, add(std::move(s), v));
}

Param<glm::vec3> Params::add_vec3(const std::string& name, glm::vec3 value, double min, double max, const std::string& help) {
    ParamSpec s;
    s.name = name, s.type = ParamType::Vec3, s.help = help, s.min = min, s.max = max;
    Value v;
    v.vec = value;
    return Param<glm::vec3>(this, add(std::move(s), v));
}

Param<std::string> Params::add_word(const std::string& name, ParamType type, const std::string& value, const std::string& help) {
    ParamSpec s;
    s.name = name, s.type = type, s.help = help;
    Value v;
    v.word = value;
    return Param<std::string>(this, add(std::move(s), v));
}

Param<std::string> Params::add_file(const std::string& name, const std::string& value, const std::string& help) {
    return add_word(name, ParamType::File, value, help);
}

Param<std::string> Params::add_text(const std::string& name, const std::string& value, const std::string& help) {
    return add_word(name, ParamType::Text, value, help);
}

Param<bool> Params::add_effect(const std::string& name, bool on, const std::string& help) {
    Param<bool> p = add_bool(name, on, help);
    specs_[p.index_].effect = true;
    p.at_compile_time("EFFECT_" + macro_name_for(name));
    return p;
}

void Params::adopt(const std::string& path, const std::string& owner, const Params& from) {
    const std::string scope = std::exchange(scope_, path), declarer = std::exchange(owner_, owner);
    try {
        for (std::size_t i = 0; i < from.specs_.size(); ++i) add(from.specs_[i], from.values_[i], true);
    } catch (...) {
        scope_ = scope, owner_ = declarer;
        throw;
    }
    scope_ = scope, owner_ = declarer;
}

void Params::check_uniform_free(const std::string& name, std::size_t index, const std::string& uniform) const {
    if (uniform.empty()) return;
    for (const auto& [reserved, setter] : reserved_uniforms_)
        if (reserved == uniform)
            throw Error("parameter '" + name + "' would set the uniform " + uniform + ", which " + setter + " sets");
    for (std::size_t i = 0; i < specs_.size(); ++i)
        if (i != index && specs_[i].uniform == uniform && specs_[i].type != ParamType::File && specs_[i].type != ParamType::Text)
            throw Error("parameter '" + name + "' would set the uniform " + uniform + ", which parameter '" + specs_[i].name + "' sets");
}

void Params::reserve_uniform(const std::string& uniform, const std::string& who) {
    for (const auto& s : specs_)
        if (s.uniform == uniform && s.type != ParamType::File && s.type != ParamType::Text)
            throw Error("parameter '" + s.name + "' would set the uniform " + uniform + ", which " + who + " sets");
    reserved_uniforms_.emplace_back(uniform, who);
}

void Params::check_condition(const std::string& param, const std::vector<std::string>& values) const {
    const std::size_t i = find_index(param);
    if (i == npos) throw Error("a condition names parameter '" + param + "', which is not declared (yet)");
    const ParamSpec& s = specs_[i];
    for (const auto& value : values) {
        const bool known = s.type == ParamType::Choice ? std::find(s.choices.begin(), s.choices.end(), value) != s.choices.end()
                           : s.type == ParamType::Bool ? value == "on" || value == "off"
                                                       : false;
        if (!known)
            throw Error("a condition on parameter '" + param + "' names '" + value + "', which is not one of its values" +
                        (s.type == ParamType::Choice || s.type == ParamType::Bool ? "" : " (conditions are on choices and switches)"));
    }
}

std::size_t Params::find_index(const std::string& name) const {
    for (std::size_t i = 0; i < specs_.size(); ++i)
        if (specs_[i].name == name || (!specs_[i].scope.empty() && specs_[i].qualified_name() == name)) return i;
    return npos;
}

std::size_t Params::index_of(const std::string& name) const {
    const std::size_t i = find_index(name);
    if (i != npos) return i;
    std::string known;
    for (const auto& s : specs_) known += (known.empty() ? "" : ", ") + s.name;
    throw Error("unknown parameter '" + name + "' (this lab has: " + known + ")");
}

std::size_t Params::read_index(const std::string& name, ParamType type) const {
    const std::size_t i = index_of(name);
    const ParamType has = specs_[i].type;
    const auto is_text = [](ParamType t) { return t == ParamType::Choice || t == ParamType::File || t == ParamType::Text; };
    if (has != type && !(is_text(type) && is_text(has)))
        throw Error("parameter '" + name + "' is " + type_name(has) + ", read as " + type_name(type));
    note_read(i);
    return i;
}

template <>
float Param<float>::get() const {
    return static_cast<float>(params_->read_value(index_).number);
}
template <>
double Param<double>::get() const {
    return params_->read_value(index_).number;
}
template <>
int Param<int>::get() const {
    return static_cast<int>(params_->read_value(index_).number);
}
template <>
bool Param<bool>::get() const {
    return params_->read_value(index_).number != 0;
}
template <>
glm::vec3 Param<glm::vec3>::get() const {
    return params_->read_value(index_).vec;
}
template <>
std::string Param<std::string>::get() const {
    return params_->read_value(index_).word;
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

void Params::set(const std::string& given, const std::string& text) {
    const std::size_t i = index_of(given);
    const ParamSpec& s = specs_[i];
    const std::string& name = s.name;
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
        v.word = text;
        v.number = static_cast<double>(it - s.choices.begin());
        break;
    }
    case ParamType::File:
        if (text.empty()) throw Error("parameter '" + name + "' needs a file path");
        v.word = text;
        break;
    case ParamType::Text: v.word = text; break;
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

std::string Params::get_text(const std::string& name) const {
    const std::size_t i = index_of(name);
    note_read(i);
    return text_at(i);
}

std::string Params::text_at(std::size_t i) const {
    const Value& v = values_.at(i);
    switch (specs_[i].type) {
    case ParamType::Float: return format_number(v.number, 7);
    case ParamType::Int: return std::to_string(static_cast<long>(v.number));
    case ParamType::Bool: return v.number != 0 ? "on" : "off";
    case ParamType::Choice:
    case ParamType::File:
    case ParamType::Text: return v.word;
    case ParamType::Vec3: return format_number(v.vec.x, 7) + "," + format_number(v.vec.y, 7) + "," + format_number(v.vec.z, 7);
    }
    return "";
}

float Params::get_float(const std::string& name) const { return static_cast<float>(values_[read_index(name, ParamType::Float)].number); }
int Params::get_int(const std::string& name) const { return static_cast<int>(values_[read_index(name, ParamType::Int)].number); }
bool Params::get_bool(const std::string& name) const { return values_[read_index(name, ParamType::Bool)].number != 0; }
const std::string& Params::get_choice(const std::string& name) const { return values_[read_index(name, ParamType::Choice)].word; }
glm::vec3 Params::get_vec3(const std::string& name) const { return values_[read_index(name, ParamType::Vec3)].vec; }
const std::string& Params::get_file(const std::string& name) const { return values_[read_index(name, ParamType::File)].word; }

void Params::nudge(const std::string& name, int steps) {
    const std::size_t i = index_of(name);
    const ParamSpec& s = specs_[i];
    Value& v = values_[i];
    switch (s.type) {
    case ParamType::File:
    case ParamType::Text: break;  // no sensible next file or text; typed on the command line
    case ParamType::Bool: v.number = v.number != 0 ? 0 : 1; break;
    case ParamType::Choice: {
        const int n = static_cast<int>(s.choices.size());
        const int k = ((static_cast<int>(v.number) + steps) % n + n) % n;
        v.number = k;
        v.word = s.choices[static_cast<std::size_t>(k)];
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
        out << "  " << s.name << " = " << text_at(i) << "  ";
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
        case ParamType::Text: out << "text"; break;
        }
        if (s.type == ParamType::File || s.type == ParamType::Text || (!s.compile_time && s.uniform.empty())) out << ", read by the lab";
        else if (s.compile_time) out << ", compiled in as " << s.define;
        else out << ", uniform " << s.uniform;
        if (!s.sweep_values.empty()) out << ", ACCURACY KNOB";
        if (!s.owner.empty()) out << ", declared by " << s.owner;
        for (const auto& condition : s.applies_when_all) {
            out << ", only where " << condition.param << "=";
            for (std::size_t k = 0; k < condition.values.size(); ++k) out << (k ? "|" : "") << condition.values[k];
        }
        out << "\n      " << s.help << "\n";
        if (!s.same_picture_why.empty()) out << "      may draw the same picture: " << s.same_picture_why << "\n";
    }
    return out.str();
}

// What would give `spec` an effect, from the other parameters' values only.
std::string Params::unmet_condition(const ParamSpec& spec) const {
    for (const auto& condition : spec.applies_when_all) {
        const std::string value = text_at(index_of(condition.param));
        if (std::find(condition.values.begin(), condition.values.end(), value) != condition.values.end()) continue;
        std::string wanted;
        for (std::size_t k = 0; k < condition.values.size(); ++k)
            wanted += (k == 0 ? "" : k + 1 == condition.values.size() ? " or " : ", ") + condition.values[k];
        return "needs " + condition.param + "=" + wanted + " (it is " + value + ")";
    }
    return {};
}

std::string Params::inactive_reason(const std::string& name) const {
    const ParamSpec& spec = specs_[index_of(name)];
    for (const auto& [feature, why] : missing_features_.why)
        if (feature == spec.gl_feature) return "needs " + why;
    return unmet_condition(spec);
}

bool Params::applies(const std::string& name) const { return inactive_reason(name).empty(); }

void Params::note_missing_feature(const std::string& feature, const std::string& why) {
    for (auto& [known, said] : missing_features_.why)
        if (known == feature) {
            said = why;
            return;
        }
    missing_features_.why.emplace_back(feature, why);
}

void Params::check_applies(const std::vector<std::string>& names, const std::string& where) const {
    for (const auto& name : names) {
        const std::string reason = unmet_condition(specs_[index_of(name)]);  // a missing GL feature greys, never refuses
        if (!reason.empty())
            throw Error(where + name + "=" + text_at(index_of(name)) + " has no effect here: it " + reason);
    }
}

}  // namespace gsv
