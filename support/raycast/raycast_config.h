#pragma once
// A modular ray caster is one skeleton with placeholders, the RC_* macros, filled at compile time with the modules
// one configuration needs. This is the machinery, for a table of modules the lab gives it (lab 06's, with its GLSL
// file names, is in its own folder): it names a configuration and writes the generated include file,
// rc_config.glsl, that fills the placeholders, so the compiled shader holds only what the configuration uses. A
// uniform `if` per module (the uber-shader) ran several times slower on llvmpipe, which is why the choice is made
// here and not in the shader.
#include "common/shader/shader_source.h"

#include <string>
#include <utility>
#include <vector>

namespace gsv {

struct RaycastConfig {
    // The enumerators' order is the module tables' rows, and so the uber-shader's uniform values. A compositing
    // table may have more rows than are named here: row i is Compositing(i).
    enum class Gradient { None, Forward, Central, Precomputed };
    enum class Classification { Raw, TransferFunction };
    enum class Shading { None, Phong };
    enum class Compositing { Dvr, Mip, Isosurface, FirstHit };

    Gradient gradient = Gradient::None;
    Classification classification = Classification::Raw;
    Shading shading = Shading::None;
    Compositing compositing = Compositing::Dvr;
    bool early_termination = true;  // DVR only: stop once the ray is opaque enough (uEarlyRayThreshold)
};

bool operator==(const RaycastConfig& a, const RaycastConfig& b);
inline bool operator!=(const RaycastConfig& a, const RaycastConfig& b) { return !(a == b); }

// A row of a module table: one module for one placeholder.
struct RaycastModule {
    const char* name;      // as a parameter spells it
    const char* file;      // its GLSL file, as the generated header includes it (the lab's folder is an include dir)
    const char* function;  // what the placeholder expands to; a compositing module's X of rcStartX, rcCompositeX...
};

// What a legend says of a compositing mode's picture.
struct CompositingLegend {
    bool shown;            // false where the colours are not data (first hit's are positions)
    const char* note;      // one sentence under the colour bar
    bool marks_iso_value;  // a mark at the iso value
};

// A compositing module has four functions, rcStart<X>, rcComposite<X>, rcTerminate<X> and rcFinish<X>; its row also
// says what it is, what it uses and what its legend says, so that a new mode is its GLSL file and its row: the
// choice and its help, the configurations tests and sweeps run, the uber-shader and the legend follow from the row.
struct CompositingModule : RaycastModule {
    const char* description;    // a few words: the parameter's help lists them
    bool shaded;                // uses the gradient and the shading (else neither is compiled in)
    bool optional_termination;  // early termination is a setting (DVR's); else it is the algorithm itself
    CompositingLegend legend;
};

// A lab's modules, one table a placeholder, each table's rows in its enum's order. A module left out (gradient
// none, shading none) is a row with neither file nor function: its placeholder gets the no-op. Checked whole when
// made: a throw of gsv::Error, one line naming the table, the row and the piece it lacks.
class RaycastModules {
public:
    RaycastModules(std::vector<RaycastModule> gradients, std::vector<RaycastModule> classifications,
                   std::vector<RaycastModule> shadings, std::vector<CompositingModule> compositings);
    // These tables and one more compositing row, checked the same way (a test's mode).
    RaycastModules with_compositing(const CompositingModule& row) const;

    const std::vector<RaycastModule>& gradients() const { return gradients_; }
    const std::vector<RaycastModule>& classifications() const { return classifications_; }
    const std::vector<RaycastModule>& shadings() const { return shadings_; }
    const std::vector<CompositingModule>& compositings() const { return compositings_; }

private:
    std::vector<RaycastModule> gradients_, classifications_, shadings_;
    std::vector<CompositingModule> compositings_;
};

// Names as a command line or a lab parameter spells them, from the tables.
const char* name_of(const RaycastModules& modules, RaycastConfig::Gradient gradient);
const char* name_of(const RaycastModules& modules, RaycastConfig::Classification classification);
const char* name_of(const RaycastModules& modules, RaycastConfig::Shading shading);
const char* name_of(const RaycastModules& modules, RaycastConfig::Compositing compositing);
// Each table's names in its rows' order: the choices of the ray caster's parameters.
std::vector<std::string> gradient_names(const RaycastModules& modules);
std::vector<std::string> classification_names(const RaycastModules& modules);
std::vector<std::string> shading_names(const RaycastModules& modules);
std::vector<std::string> compositing_names(const RaycastModules& modules);
// The compositing parameter's help, a phrase a row: "dvr: direct volume rendering, mip: maximum intensity, ...".
std::string compositing_help(const RaycastModules& modules);
// Throw gsv::Error, one line naming the bad value and the known ones.
RaycastConfig::Gradient parse_gradient(const RaycastModules& modules, const std::string& name);
RaycastConfig::Classification parse_classification(const RaycastModules& modules, const std::string& name);
RaycastConfig::Shading parse_shading(const RaycastModules& modules, const std::string& name);
RaycastConfig::Compositing parse_compositing(const RaycastModules& modules, const std::string& name);

// "compositing dvr, gradient central, classification tf, shading phong, early termination on"
std::string describe(const RaycastModules& modules, const RaycastConfig& config);

// Throws gsv::Error (one line) for a request that cannot be met: Phong shading without a gradient to
// take the normal from. Checked on the request as given, whatever the compositing.
void validate(const RaycastModules& modules, const RaycastConfig& config);

// What the compositing can use of the request. A module the compositing cannot use is not compiled in,
// even when asked for: a mode that is not `shaded` uses neither gradient nor shading; a shaded one uses the
// gradient only to shade; early termination is a setting only where the row says so (DVR's: MIP never stops
// early, isosurface and first hit always stop at their hit). Asking is not an error: a lab's settings can stay
// put while the compositing changes. The generated header names the result.
RaycastConfig effective_config(const RaycastModules& modules, const RaycastConfig& config);

CompositingLegend compositing_legend(const RaycastModules& modules, RaycastConfig::Compositing compositing);

// Every configuration validate() accepts, early termination on, over every row of every table: for lab 06's,
// 56 of the 4 x 2 x 2 x 4 (Phong without a gradient is refused), for tests and sweeps.
std::vector<RaycastConfig> all_raycast_configs(const RaycastModules& modules);

// The name the skeleton includes and the text of it for `config`: #include lines for the chosen modules,
// #define RC_...(args) lines naming their functions, no-op defines for the modules left out, and a
// comment naming the configuration. Validates first (throws as validate() does).
inline constexpr const char* kRaycastConfigFile = "rc_config.glsl";
std::string generate_raycast_header(const RaycastModules& modules, const RaycastConfig& config);
// {kRaycastConfigFile, generate_raycast_header(modules, config)}: ready for ProgramSpec::generated.
GeneratedFile raycast_config_file(const RaycastModules& modules, const RaycastConfig& config);

// The uber-shader's modules, generated from the same tables (the uber-shader includes it): every module's file,
// the mode uniforms, and the RC_* placeholders defined as functions that pick a module per draw by those
// uniforms, one branch a row, so no mode can fall through to another's.
inline constexpr const char* kRaycastUberFile = "rc_uber.glsl";
std::string generate_raycast_uber_header(const RaycastModules& modules);
GeneratedFile raycast_uber_file(const RaycastModules& modules);  // {kRaycastUberFile, generate_raycast_uber_header(modules)}

// The mode uniforms the uber-shader reads (uGradientMode, uClassificationMode, uShadingMode,
// uCompositingMode, uEarlyTermination) for the effective configuration, so the uber-shader computes the
// image the specialised shader does and skips what it skips. Validates first.
std::vector<std::pair<std::string, int>> raycast_uber_uniforms(const RaycastModules& modules, const RaycastConfig& config);

}  // namespace gsv
