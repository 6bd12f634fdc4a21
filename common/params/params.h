#pragma once
// A lab's parameters, declared once, typed, by whoever uses them (the lab, a processor of its network, a shader
// component), and then served everywhere: the command line (--set name=value), case files, network files, the
// window's panel and the web page's controls, sweeps, change tracking, uniforms (u<Name>) and compile-time
// #defines (common/shader/param_uniforms.h).
//
// Declaring gives a typed handle that reads the value as its type, with no text in between; whoever declares keeps
// the handle (a member) and reads through it:
//     gsv::Param<float> samples = p.add_float("samples_per_voxel", 1, 0.05, 32, "samples along a ray per voxel");
//     const float step = 1.0f / (samples.get() * n);
// A choice is an enum's name table (common/core/enum_names.h; support/ exports its own), read as the enum, so a
// misspelt choice is a misspelt enumerator, which does not compile:
//     gsv::EnumParam<gsv::Integrator> integrator = p.add_enum("integrator", gsv::Integrator::Euler, gsv::kIntegratorNames, "...");
//     if (integrator.get() == gsv::Integrator::Rk4) ...
// Reading by name (get_float("alpha"), get_text) is for generic code: the panel, sweeps, reports, case files.
// Processors' parameters adopted by a lab (Params::adopt) keep their own names on the command line and are also
// known by the processor's ("raycaster.samples_per_voxel").
#include "common/core/enum_names.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <initializer_list>
#include <optional>
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
template <class V>
class EnumParam;

// The type itself, where deducing it would clash (a braced list of an enum's values read as OneOf).
template <class T>
struct TypeIdentity {
    using type = T;
};
template <class T>
using TypeIdentityT = typename TypeIdentity<T>::type;

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
    // Reaches shaders through this uniform, not u<Name>; refused where another parameter or the kit has that uniform.
    Param& with_uniform(std::string uniform);
    // Reaches no shader: the lab alone reads it (lab 02's `input` picks which texture to make; uInput is that texture).
    Param& without_uniform();
    Param& with_step(double step);
    Param& accuracy_knob(std::vector<std::string> values_least_accurate_first);
    Param& series();
    Param& animated();
    // Has an effect only while a choice is one of `values` ("field_file" only while field=file), or while a switch is
    // on (or off). Chainable: all hold. By name, the parameter must be declared already and the values be its own.
    template <class V>
    Param& applies_when(const EnumParam<V>& choice, std::initializer_list<TypeIdentityT<V>> values);
    Param& applies_when(const Param<bool>& flag, bool on);
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

namespace param_detail {
// The name of `value` in `names`; "unknown" where it has none.
template <class V>
const char* name_in(const std::vector<EnumName<V>>& names, const V& value) {
    for (const auto& entry : names)
        if (entry.value == value) return entry.name;
    return "unknown";
}
template <class V>
std::vector<std::string> choice_names(const std::vector<EnumName<V>>& names) {
    std::vector<std::string> out;
    for (const auto& entry : names) out.push_back(entry.name);
    return out;
}
}  // namespace param_detail

// One value of either of two enums: a choice of a support table's names with the lab's own beside them (lab 02's
// field: support/flow's analytic flows, the swirl, a file). Compares with either's values; as<T>() is the one of T.
template <class A, class B>
class OneOf {
public:
    static_assert(!std::is_same_v<A, B>, "OneOf of two different enums");
    OneOf(A a) : a_(a) {}
    OneOf(B b) : b_(b) {}
    template <class T>
    std::optional<T> as() const {
        static_assert(std::is_same_v<T, A> || std::is_same_v<T, B>, "as<T>: T is one of OneOf's two enums");
        if constexpr (std::is_same_v<T, A>) return a_;
        else return b_;
    }
    friend bool operator==(const OneOf& x, const OneOf& y) { return x.a_ == y.a_ && x.b_ == y.b_; }
    friend bool operator!=(const OneOf& x, const OneOf& y) { return !(x == y); }

private:
    std::optional<A> a_;
    std::optional<B> b_;
};

// A choice read as a value of V: an enum whose name table declared it (Params::add_enum), or OneOf two enums. The
// declaration's refinements are Param's.
template <class V>
class EnumParam {
public:
    using Value = V;
    EnumParam() = default;
    EnumParam(Param<std::string> choice, std::vector<EnumName<V>> names) : choice_(std::move(choice)), names_(std::move(names)) {}
    V get() const;  // notes the read, as Param::get
    V operator*() const { return get(); }
    bool declared() const { return choice_.declared(); }
    const Param<std::string>& param() const { return choice_; }
    const std::string& name() const { return choice_.name(); }
    const char* name_of(V value) const;

    EnumParam& at_compile_time(std::string macro = "") { return refined(choice_.at_compile_time(std::move(macro))); }
    EnumParam& without_uniform() { return refined(choice_.without_uniform()); }
    EnumParam& series() { return refined(choice_.series()); }
    EnumParam& may_draw_the_same(std::string why) { return refined(choice_.may_draw_the_same(std::move(why))); }
    template <class W>
    EnumParam& applies_when(const EnumParam<W>& choice, std::initializer_list<TypeIdentityT<W>> values) {
        return refined(choice_.applies_when(choice, values));
    }
    EnumParam& applies_when(const Param<bool>& flag, bool on) { return refined(choice_.applies_when(flag, on)); }

private:
    EnumParam& refined(const Param<std::string>&) { return *this; }
    Param<std::string> choice_;
    std::vector<EnumName<V>> names_;
};

class Params {
public:
    // Copies keep their own read log; assigning one made from the same declarations (a lab's defaults) changes
    // only values, so the handles into this object stay valid.

    Param<float> add_float(const std::string& name, double value, double min, double max, const std::string& help);
    Param<int> add_int(const std::string& name, int value, int min, int max, const std::string& help);
    Param<bool> add_bool(const std::string& name, bool value, const std::string& help);
    Param<std::string> add_choice(const std::string& name, const std::string& value, std::vector<std::string> choices,
                                  const std::string& help);
    // A choice of an enum's names, in the table's order, read as the enum.
    template <class E, std::size_t N>
    EnumParam<E> add_enum(const std::string& name, E value, const EnumName<E> (&table)[N], const std::string& help) {
        std::vector<EnumName<E>> names(std::begin(table), std::end(table));
        Param<std::string> choice =
            add_choice(name, param_detail::name_in(names, value), param_detail::choice_names(names), help);
        return EnumParam<E>(std::move(choice), std::move(names));
    }
    // A choice of two enums' names, the first table's then the second's (support's and the lab's own), read as OneOf.
    template <class A, std::size_t N, class B, std::size_t M>
    EnumParam<OneOf<A, B>> add_enum(const std::string& name, TypeIdentityT<OneOf<A, B>> value, const EnumName<A> (&first)[N],
                                    const EnumName<B> (&second)[M], const std::string& help) {
        std::vector<EnumName<OneOf<A, B>>> names;
        for (const auto& entry : first) names.push_back({entry.value, entry.name});
        for (const auto& entry : second) names.push_back({entry.value, entry.name});
        Param<std::string> choice =
            add_choice(name, param_detail::name_in(names, value), param_detail::choice_names(names), help);
        return EnumParam<OneOf<A, B>>(std::move(choice), std::move(names));
    }
    Param<glm::vec3> add_vec3(const std::string& name, glm::vec3 value, double min, double max, const std::string& help);
    // A path typed by the user (a data file). Never a uniform or a define; the lab resolves it with
    // Assets::user_file, which gives one-line errors naming the path.
    Param<std::string> add_file(const std::string& name, const std::string& value, const std::string& help);
    // Any words, empty included (a label, a message); never a uniform or a define.
    Param<std::string> add_text(const std::string& name, const std::string& value, const std::string& help);
    // A compile-time switch named EFFECT_<NAME> in GLSL.
    Param<bool> add_effect(const std::string& name, bool on, const std::string& help);

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

    // A uniform something other than a parameter sets on the lab's programs (the kit's transforms): a parameter whose
    // uniform it is, declared before or after, is refused, naming `who` sets it.
    void reserve_uniform(const std::string& uniform, const std::string& who);

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
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);
    struct Value {
        double number = 0;
        glm::vec3 vec{0};
        std::string word;
    };
    std::size_t add(ParamSpec spec, Value value, bool adopted = false);
    // Throws where `uniform` is another parameter's (not the one at `index`) or reserved: two setters, one uniform.
    void check_uniform_free(const std::string& name, std::size_t index, const std::string& uniform) const;
    // Throws where `param` is not declared yet or one of `values` is not one of its values.
    void check_condition(const std::string& param, const std::vector<std::string>& values) const;
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
    std::string scope_, owner_;  // while adopt declares: where the declarations go
    std::vector<std::pair<std::string, std::string>> reserved_uniforms_;  // uniform, who sets it
    mutable ReadLogSlot read_log_;
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
    params_->check_uniform_free(spec().name, index_, uniform);
    declaration().uniform = std::move(uniform);
    return *this;
}
template <class T>
Param<T>& Param<T>::without_uniform() {
    declaration().uniform.clear();
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
    params_->check_condition(param, values);
    declaration().applies_when_all.push_back({std::move(param), std::move(values)});
    return *this;
}
template <class T>
template <class V>
Param<T>& Param<T>::applies_when(const EnumParam<V>& choice, std::initializer_list<TypeIdentityT<V>> values) {
    std::vector<std::string> names;
    for (const V& value : values) names.push_back(choice.name_of(value));
    return applies_when(choice.name(), std::move(names));
}
template <class T>
Param<T>& Param<T>::applies_when(const Param<bool>& flag, bool on) {
    return applies_when(flag.name(), {on ? "on" : "off"});
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

template <class V>
V EnumParam<V>::get() const {
    const std::string name = choice_.get();
    for (const auto& entry : names_)
        if (name == entry.name) return entry.value;
    return names_.at(0).value;  // a choice holds one of its names: unreachable
}

template <class V>
const char* EnumParam<V>::name_of(V value) const {
    return param_detail::name_in(names_, value);
}

}  // namespace gsv
