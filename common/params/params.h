#pragma once
// A lab's parameters, declared once, typed, by whoever uses them (the lab, a processor of its network, a shader
// component), and then served everywhere: the command line (--set name=value), case files, network files, the
// window's panel and the web page's controls, sweeps, change tracking, uniforms (u<Name>) and compile-time
// #defines (common/shader/param_uniforms.h).
//
// Declaring gives a typed handle that reads the value as its type, with no text in between:
//     gsv::Param<float> samples = p.add_float("samples_per_voxel", 1, 0.05, 32, "samples along a ray per voxel");
//     const float step = 1.0f / (samples.get() * n);
// A scope (Params::scope) groups what one owner declares ("raycaster", a processor): its parameters keep their
// own names on the command line and are also known by the scope's ("raycaster.samples_per_voxel").
#include "common/core/enum_names.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace gsv {

enum class ParamType { Float, Int, Bool, Choice, Vec3, File, Text };

struct ParamSpec {
    std::string name;   // as typed on the command line: "alpha", "mesh_resolution"
    ParamType type = ParamType::Float;
    std::string help;
    double min = 0, max = 1;           // Float, Int, and each Vec3 component
    double step = 0;                   // window-mode increment; 0 = (max - min) / 50, or 1 for Int
    std::vector<std::string> choices;  // Choice
    bool compile_time = false;         // a #define: changing it rebuilds the lab's shaders
    bool effect = false;               // a compile-time switch: an effect that is off is not compiled in
    std::string uniform;               // runtime parameters reach shaders through this uniform
    std::string define;                // compile-time parameters through this macro
    std::vector<std::string> sweep_values;  // set on the accuracy knob: its values, least accurate first
    bool sweep_series = false;         // a Choice swept as separate curves beside the knob
    bool animation_axis = false;       // a Float that window mode plays and `animate` steps through
    std::string scope;                 // who declared it: "" for the lab, "raycaster" for a processor
    std::string owner;                 // that owner in words, for `list`: "RayTraversal 'raycaster'"
    // When the parameter has an effect: every condition holds (another parameter's value is one of these). Setting
    // it where it has none is an error (Params::check_applies); the window greys it out.
    struct Condition {
        std::string param;
        std::vector<std::string> values;
    };
    std::vector<Condition> applies_when_all;
    // The GL feature it acts through (its name in common/gl/gl_features.h): in a context without it (lab 05's local_size
    // on OpenGL ES 3.0, where transform feedback takes no work groups) it is greyed with the reason, not refused, so a
    // case that sets it grades alike everywhere.
    std::string gl_feature;
    // Why changing it may leave the picture as it was (it changes how, not what, or shows only under other values): said
    // beside the control, so a student who moves it and sees nothing is told why, not left to guess.
    std::string same_picture_why;

    std::string qualified_name() const { return scope.empty() ? name : scope + "." + name; }
};

// The macro a compile-time parameter's name becomes: "time_wrap" -> "TIME_WRAP".
std::string macro_name_for(const std::string& name);

class Params;

// A declared parameter's handle, read as T: float, int, bool, glm::vec3, or std::string (a choice, a file, a text).
// The chainable refinements are for the declaration ("with_step(0.25).accuracy_knob(...)").
template <class T>
class Param {
public:
    Param() = default;  // declared nowhere yet
    T get() const;      // notes the read for change tracking (common/params/change_tracker.h)
    T operator*() const { return get(); }
    bool declared() const { return params_ != nullptr; }
    // A float read in double, as typed, not rounded to float on the way (a step that is a reciprocal).
    Param<double> in_double() const { return Param<double>(params_, index_); }
    const ParamSpec& spec() const;
    const std::string& name() const { return spec().name; }

    Param& at_compile_time(std::string macro = "");
    Param& with_uniform(std::string uniform);
    Param& with_step(double step);
    Param& accuracy_knob(std::vector<std::string> values_least_accurate_first);
    Param& series();
    Param& animated();
    // Has an effect only while `param` is one of `values` ("field_file" only while field=file). Chainable: all hold.
    Param& applies_when(std::string param, std::vector<std::string> values);
    // Has an effect only in a context with this GL feature (gsv::gl_feature::kCompute.name).
    Param& acts_through(std::string gl_feature);
    // Changing it may draw the same picture, and why ("the same slices from a 3D texture: the same picture, another cost").
    Param& may_draw_the_same(std::string why);

private:
    friend class Params;
    template <class U>
    friend class Param;
    Param(Params* params, std::size_t index) : params_(params), index_(index) {}
    ParamSpec& declaration();
    Params* params_ = nullptr;
    std::size_t index_ = 0;
};

// A choice whose names are an enum's name table (common/core/enum_names.h): read as the enum.
template <class E>
class EnumParam {
public:
    EnumParam() = default;
    template <std::size_t N>
    EnumParam(Param<std::string> choice, const EnumName<E> (&table)[N]) : choice_(std::move(choice)), table_(table), size_(N) {}
    E get() const;
    E operator*() const { return get(); }
    const Param<std::string>& param() const { return choice_; }
    Param<std::string>& param() { return choice_; }

private:
    Param<std::string> choice_;
    const EnumName<E>* table_ = nullptr;
    std::size_t size_ = 0;
};

class ParamScope;

class Params {
public:
    // Copies keep their own read log; assigning one made from the same declarations (a lab's defaults) changes
    // only values, so the handles into this object stay valid.

    Param<float> add_float(const std::string& name, double value, double min, double max, const std::string& help);
    Param<int> add_int(const std::string& name, int value, int min, int max, const std::string& help);
    Param<bool> add_bool(const std::string& name, bool value, const std::string& help);
    Param<std::string> add_choice(const std::string& name, const std::string& value, std::vector<std::string> choices,
                                  const std::string& help);
    // A choice of an enum's names, read as the enum.
    template <class E, std::size_t N>
    EnumParam<E> add_enum(const std::string& name, E value, const EnumName<E> (&table)[N], const std::string& help) {
        std::vector<std::string> names;
        for (const auto& entry : table) names.push_back(entry.name);
        return EnumParam<E>(add_choice(name, name_of(table, value), std::move(names), help), table);
    }
    Param<glm::vec3> add_vec3(const std::string& name, glm::vec3 value, double min, double max, const std::string& help);
    // A path typed by the user (a data file). Never a uniform or a define; the lab resolves it with
    // Assets::user_file, which gives one-line errors naming the path.
    Param<std::string> add_file(const std::string& name, const std::string& value, const std::string& help);
    // Any words, empty included (a label, a message); never a uniform or a define.
    Param<std::string> add_text(const std::string& name, const std::string& value, const std::string& help);
    // A compile-time switch named EFFECT_<NAME> in GLSL.
    Param<bool> add_effect(const std::string& name, bool on, const std::string& help);

    // What `owner` declares, under `path`: its parameters are known by their own names and as "path.name".
    ParamScope scope(const std::string& path, const std::string& owner);
    // Declares here, under `path`, every parameter `from` declares, with its value: a processor's declarations
    // made part of the lab's (each still declared once, by the processor's type).
    void adopt(const std::string& path, const std::string& owner, const Params& from);
    // Each parameter of this one that `from` declares too, of the same type, takes its value, typed, unless `keep`
    // holds for its name: a processor following the lab's parameters. Found as "path.name", else by its own name
    // (a network file's processor named otherwise than the one adopted still follows).
    template <class Keep>
    void follow(const Params& from, const std::string& path, Keep&& keep) {
        for (std::size_t i = 0; i < specs_.size(); ++i) {
            std::size_t j = path.empty() ? npos : from.find_index(path + "." + specs_[i].name);
            if (j == npos) j = from.find_index(specs_[i].name);
            if (j == npos || from.specs_[j].type != specs_[i].type || keep(specs_[i].name)) continue;
            values_[i] = from.values_[j];
        }
    }

    // Parses and validates; throws gsv::Error naming the parameter, the value and the allowed range. `name` is a
    // parameter's own name or its qualified one.
    void set(const std::string& name, const std::string& text);
    // "name=value"
    void set_assignment(const std::string& assignment);
    std::string get_text(const std::string& name) const;
    bool has(const std::string& name) const { return find_index(name) != npos; }

    // Reads by name, for code that does not keep the handle; each throws naming the parameter when it has another type.
    float get_float(const std::string& name) const;
    int get_int(const std::string& name) const;
    bool get_bool(const std::string& name) const;
    const std::string& get_choice(const std::string& name) const;
    glm::vec3 get_vec3(const std::string& name) const;
    const std::string& get_file(const std::string& name) const;
    // The handle of a declared parameter, by name and type (throws naming the type it has): to refine a
    // declaration made elsewhere (a processor's, adopted), or to read it.
    template <class T>
    Param<T> param(const std::string& name);

    // Window controls: move a parameter by `steps` increments (Bool toggles, Choice cycles), clamped.
    void nudge(const std::string& name, int steps);

    // Change tracking (common/params/change_tracker.h). While a read log is set, every parameter read is added to
    // it: through a getter or a handle, and where common/shader/param_uniforms.h reads it for a program in use.
    // Returns the log that was set before.
    std::vector<std::size_t>* swap_read_log(std::vector<std::size_t>* log) const;
    // Adds reads to the log in place, if any (a nested tracker that had nothing to remake reports what it read).
    void note_reads(const std::vector<std::size_t>& indices) const;
    // The value of the parameter at `index` as text, without noting a read.
    std::string text_at(std::size_t index) const;
    // The value at `index` without noting a read: a number (Float, Int, Bool as 0/1, Choice as its index), a
    // vector, a word (Choice, File). For code that sets uniforms and defines, which notes its reads itself.
    double number_at(std::size_t index) const { return values_.at(index).number; }
    glm::vec3 vec3_at(std::size_t index) const { return values_.at(index).vec; }
    const std::string& word_at(std::size_t index) const { return values_.at(index).word; }

    const std::vector<ParamSpec>& specs() const { return specs_; }
    const ParamSpec& spec(const std::string& name) const;  // throws naming the unknown parameter and the known ones
    const ParamSpec* knob() const;
    const ParamSpec* series() const;
    const ParamSpec* animation_axis() const;
    std::string describe() const;  // one line per parameter: name, type, range, default, help

    // Whether the parameter has an effect under the current values (its applies_when conditions hold); no read is
    // noted. inactive_reason: empty where it applies, else what would enable it: "needs field=file (it is rotation)".
    bool applies(const std::string& name) const;
    std::string inactive_reason(const std::string& name) const;
    // Throws gsv::Error for the first of `names` (parameters the user set) that has no effect under the current
    // values: "<where>field_file has no effect while field=rotation: it needs field=file".
    void check_applies(const std::vector<std::string>& names, const std::string& where) const;
    // What the session's GL context lacks, said once it is made: a parameter that acts through it is greyed with `why`
    // ("compute shaders and storage buffers, which OpenGL ES 3.1 has; this context is OpenGL ES 3.0").
    void note_missing_feature(const std::string& feature, const std::string& why);

private:
    template <class T>
    friend class Param;
    friend class ParamScope;
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);
    struct Value {
        double number = 0;
        glm::vec3 vec{0};
        std::string word;
    };
    std::size_t add(ParamSpec spec, Value value);
    Param<std::string> add_word(const std::string& name, ParamType type, const std::string& value, const std::string& help);
    std::size_t index_of(const std::string& name) const;  // throws listing the known parameters
    std::size_t find_index(const std::string& name) const;  // npos when none
    std::string unmet_condition(const ParamSpec& spec) const;  // inactive_reason without the context's features
    std::size_t read_index(const std::string& name, ParamType type) const;  // index_of, type checked, noted as read
    void note_read(std::size_t index) const {
        if (read_log_.log) read_log_.log->push_back(index);
    }
    const Value& read_value(std::size_t index) const {  // what a handle reads: noted
        note_read(index);
        return values_[index];
    }
    // The read log belongs to this object: a copy starts without one, and assigning values keeps this one's.
    struct ReadLogSlot {
        std::vector<std::size_t>* log = nullptr;
        ReadLogSlot() = default;
        ReadLogSlot(const ReadLogSlot&) {}
        ReadLogSlot& operator=(const ReadLogSlot&) { return *this; }
    };
    // The context's missing features belong to this object, as the read log does: assigning values (a lab's defaults, the
    // last values that drew) keeps them.
    struct MissingFeatures {
        std::vector<std::pair<std::string, std::string>> why;  // feature name, what to say
        MissingFeatures() = default;
        MissingFeatures(const MissingFeatures&) = default;
        MissingFeatures& operator=(const MissingFeatures&) { return *this; }
    };
    std::vector<ParamSpec> specs_;
    std::vector<Value> values_;
    MissingFeatures missing_features_;
    std::string scope_, owner_;  // while a ParamScope declares: where the declarations go
    mutable ReadLogSlot read_log_;
};

// Declarations under one owner's name: the same calls as Params'.
class ParamScope {
public:
    ParamScope(Params& params, std::string path, std::string owner) : params_(params), path_(std::move(path)), owner_(std::move(owner)) {}
    Param<float> add_float(const std::string& name, double value, double min, double max, const std::string& help) {
        const Declaring in(*this);
        return params_.add_float(name, value, min, max, help);
    }
    Param<int> add_int(const std::string& name, int value, int min, int max, const std::string& help) {
        const Declaring in(*this);
        return params_.add_int(name, value, min, max, help);
    }
    Param<bool> add_bool(const std::string& name, bool value, const std::string& help) {
        const Declaring in(*this);
        return params_.add_bool(name, value, help);
    }
    Param<std::string> add_choice(const std::string& name, const std::string& value, std::vector<std::string> choices,
                                  const std::string& help) {
        const Declaring in(*this);
        return params_.add_choice(name, value, std::move(choices), help);
    }
    template <class E, std::size_t N>
    EnumParam<E> add_enum(const std::string& name, E value, const EnumName<E> (&table)[N], const std::string& help) {
        const Declaring in(*this);
        return params_.add_enum(name, value, table, help);
    }
    Param<glm::vec3> add_vec3(const std::string& name, glm::vec3 value, double min, double max, const std::string& help) {
        const Declaring in(*this);
        return params_.add_vec3(name, value, min, max, help);
    }
    Param<std::string> add_file(const std::string& name, const std::string& value, const std::string& help) {
        const Declaring in(*this);
        return params_.add_file(name, value, help);
    }
    Param<std::string> add_text(const std::string& name, const std::string& value, const std::string& help) {
        const Declaring in(*this);
        return params_.add_text(name, value, help);
    }
    Params& params() { return params_; }
    const std::string& path() const { return path_; }

private:
    // While it lives, what the Params declares belongs to this scope.
    struct Declaring {
        explicit Declaring(ParamScope& scope) : params(scope.params_), scope(std::exchange(params.scope_, scope.path_)),
                                                owner(std::exchange(params.owner_, scope.owner_)) {}
        ~Declaring() {
            params.scope_ = scope;
            params.owner_ = owner;
        }
        Params& params;
        std::string scope, owner;
    };
    Params& params_;
    std::string path_, owner_;
};

// Handles read their parameter's value in their own type.
template <>
float Param<float>::get() const;
template <>
double Param<double>::get() const;
template <>
int Param<int>::get() const;
template <>
bool Param<bool>::get() const;
template <>
glm::vec3 Param<glm::vec3>::get() const;
template <>
std::string Param<std::string>::get() const;

template <class T>
Param<T> Params::param(const std::string& name) {
    ParamType type = ParamType::Text;
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) type = ParamType::Float;
    else if constexpr (std::is_same_v<T, int>) type = ParamType::Int;
    else if constexpr (std::is_same_v<T, bool>) type = ParamType::Bool;
    else if constexpr (std::is_same_v<T, glm::vec3>) type = ParamType::Vec3;
    return Param<T>(this, read_index(name, type));
}

template <class T>
const ParamSpec& Param<T>::spec() const {
    return params_->specs_.at(index_);
}
template <class T>
ParamSpec& Param<T>::declaration() {
    return params_->specs_.at(index_);
}
template <class T>
Param<T>& Param<T>::at_compile_time(std::string macro) {
    ParamSpec& s = declaration();
    s.compile_time = true;
    s.define = macro.empty() ? macro_name_for(s.name) : std::move(macro);
    return *this;
}
template <class T>
Param<T>& Param<T>::with_uniform(std::string uniform) {
    declaration().uniform = std::move(uniform);
    return *this;
}
template <class T>
Param<T>& Param<T>::with_step(double step) {
    declaration().step = step;
    return *this;
}
template <class T>
Param<T>& Param<T>::accuracy_knob(std::vector<std::string> values) {
    declaration().sweep_values = std::move(values);
    return *this;
}
template <class T>
Param<T>& Param<T>::series() {
    declaration().sweep_series = true;
    return *this;
}
template <class T>
Param<T>& Param<T>::animated() {
    declaration().animation_axis = true;
    return *this;
}
template <class T>
Param<T>& Param<T>::applies_when(std::string param, std::vector<std::string> values) {
    declaration().applies_when_all.push_back({std::move(param), std::move(values)});
    return *this;
}
template <class T>
Param<T>& Param<T>::may_draw_the_same(std::string why) {
    declaration().same_picture_why = std::move(why);
    return *this;
}
template <class T>
Param<T>& Param<T>::acts_through(std::string gl_feature) {
    declaration().gl_feature = std::move(gl_feature);
    return *this;
}

template <class E>
E EnumParam<E>::get() const {
    const std::string name = choice_.get();
    for (std::size_t i = 0; i < size_; ++i)
        if (name == table_[i].name) return table_[i].value;
    return table_[0].value;  // a choice holds one of the table's names: unreachable
}

}  // namespace gsv
