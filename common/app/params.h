#pragma once
// A lab's parameters, declared once and then served everywhere: the command line (--set name=value),
// window controls, sweeps, grader cases, uniforms (u<Name>) and compile-time #defines.
#include "common/shader/shader_source.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace gsv {

class ShaderProgram;

enum class ParamType { Float, Int, Bool, Choice, Vec3, File };

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
    // When the parameter has an effect: every condition holds (another parameter's value is one of these). Setting
    // it where it has none is an error (Params::check_applies); the window greys it out.
    struct Condition {
        std::string param;
        std::vector<std::string> values;
    };
    std::vector<Condition> applies_when_all;

    // Chainable refinements for declarations that read like a table.
    ParamSpec& at_compile_time(std::string macro = "");
    ParamSpec& with_uniform(std::string name) { uniform = std::move(name); return *this; }
    ParamSpec& with_step(double s) { step = s; return *this; }
    ParamSpec& accuracy_knob(std::vector<std::string> values_least_accurate_first);
    ParamSpec& series() { sweep_series = true; return *this; }
    ParamSpec& animated() { animation_axis = true; return *this; }
    // Has an effect only while `param` is one of `values` ("field_file" only while field=file). Chainable: all hold.
    ParamSpec& applies_when(std::string param, std::vector<std::string> values);
};

class Params {
public:
    ParamSpec& add_float(const std::string& name, double value, double min, double max, const std::string& help);
    ParamSpec& add_int(const std::string& name, int value, int min, int max, const std::string& help);
    ParamSpec& add_bool(const std::string& name, bool value, const std::string& help);
    ParamSpec& add_choice(const std::string& name, const std::string& value, std::vector<std::string> choices,
                          const std::string& help);
    ParamSpec& add_vec3(const std::string& name, glm::vec3 value, double min, double max, const std::string& help);
    // A path typed by the user (a data file). Never a uniform or a define; the lab resolves it with
    // Assets::user_file, which gives one-line errors naming the path.
    ParamSpec& add_file(const std::string& name, const std::string& value, const std::string& help);
    // A compile-time switch named EFFECT_<NAME> in GLSL.
    ParamSpec& add_effect(const std::string& name, bool on, const std::string& help);

    // Parses and validates; throws gsv::Error naming the parameter, the value and the allowed range.
    void set(const std::string& name, const std::string& text);
    // "name=value"
    void set_assignment(const std::string& assignment);
    std::string get_text(const std::string& name) const;

    float get_float(const std::string& name) const;
    int get_int(const std::string& name) const;
    bool get_bool(const std::string& name) const;
    const std::string& get_choice(const std::string& name) const;
    glm::vec3 get_vec3(const std::string& name) const;
    const std::string& get_file(const std::string& name) const;

    // Window controls: move a parameter by `steps` increments (Bool toggles, Choice cycles), clamped.
    void nudge(const std::string& name, int steps);

    std::vector<ShaderDefine> defines() const;
    // Sets every runtime parameter's uniform on `program`, which must be in use; a sampler of that name is left on
    // its texture unit.
    void apply_uniforms(const ShaderProgram& program) const;

    // Change tracking (common/app/change_tracker.h). While a read log is set, every parameter read is added to it:
    // through a getter, as an active uniform of a program in use (apply_uniforms), and every compile-time one
    // when a program is used (each is compiled into every program). Returns the log that was set before.
    std::vector<std::size_t>* swap_read_log(std::vector<std::size_t>* log) const;
    // Adds reads to the log in place, if any (a nested tracker that had nothing to remake reports what it read).
    void note_reads(const std::vector<std::size_t>& indices) const;
    // The value of the parameter at `index` as text, without noting a read.
    std::string text_at(std::size_t index) const;

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

private:
    struct Value {
        double number = 0;
        glm::vec3 vec{0};
        std::string choice;
    };
    ParamSpec& add(ParamSpec spec, Value value);
    std::size_t index_of(const std::string& name) const;
    std::size_t read_index(const std::string& name) const;  // index_of, noted in the read log
    // The read log belongs to this object: a copy starts without one, and assigning values keeps this one's.
    struct ReadLogSlot {
        std::vector<std::size_t>* log = nullptr;
        ReadLogSlot() = default;
        ReadLogSlot(const ReadLogSlot&) {}
        ReadLogSlot& operator=(const ReadLogSlot&) { return *this; }
    };
    std::vector<ParamSpec> specs_;
    std::vector<Value> values_;
    mutable ReadLogSlot read_log_;
};

}  // namespace gsv
