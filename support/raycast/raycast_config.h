#pragma once
// Lab 06's ray caster is one skeleton (solutions/lab06_raycasting/raycast.frag) with placeholders, the RC_* macros,
// filled at compile time with the modules one configuration needs. This names a configuration and writes
// the generated include file, rc_config.glsl, that fills the placeholders: the compiled shader then holds
// only what the configuration uses. A uniform `if` per module (raycast_uber.frag) ran several times
// slower on llvmpipe, which is why the choice is made here and not in the shader.
#include "common/shader/shader_source.h"

#include <string>
#include <utility>
#include <vector>

namespace gsv {

struct RaycastConfig {
    // The enumerators' order is the uber-shader's uniform values (raycast_uber.frag): keep them in step.
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

// Names as a command line or a lab parameter spells them: none forward central precomputed | raw tf |
// none phong | dvr mip iso fhp.
const char* name_of(RaycastConfig::Gradient gradient);
const char* name_of(RaycastConfig::Classification classification);
const char* name_of(RaycastConfig::Shading shading);
const char* name_of(RaycastConfig::Compositing compositing);
// Each table's names in its enum's order: the choices of the ray caster's parameters.
std::vector<std::string> gradient_names();
std::vector<std::string> classification_names();
std::vector<std::string> shading_names();
std::vector<std::string> compositing_names();
// Throw gsv::Error, one line naming the bad value and the known ones.
RaycastConfig::Gradient parse_gradient(const std::string& name);
RaycastConfig::Classification parse_classification(const std::string& name);
RaycastConfig::Shading parse_shading(const std::string& name);
RaycastConfig::Compositing parse_compositing(const std::string& name);

// "compositing dvr, gradient central, classification tf, shading phong, early termination on"
std::string describe(const RaycastConfig& config);

// Throws gsv::Error (one line) for a request that cannot be met: Phong shading without a gradient to
// take the normal from. Checked on the request as given, whatever the compositing.
void validate(const RaycastConfig& config);

// What the compositing can use of the request. A module the compositing cannot use is not compiled in,
// even when asked for: MIP and first hit use neither gradient nor shading; DVR and isosurface use the
// gradient only to shade; early termination is DVR's (MIP never stops early, isosurface and first hit
// always stop at their hit). Asking is not an error: a lab's settings can stay put while the compositing
// changes. The generated header names the result.
RaycastConfig effective_config(const RaycastConfig& config);

// What a legend says of a compositing mode's picture, from its row of the module table.
struct CompositingLegend {
    bool shown;            // false where the colours are not data (first hit's are positions)
    const char* note;      // one sentence under the colour bar
    bool marks_iso_value;  // a mark at the iso value
};
CompositingLegend compositing_legend(RaycastConfig::Compositing compositing);

// Every configuration validate() accepts, early termination on, over every row of every module table: 56 of the
// 4 x 2 x 2 x 4 (Phong without a gradient is refused), for tests and sweeps.
std::vector<RaycastConfig> all_raycast_configs();

// The name raycast.frag includes and the text of it for `config`: #include lines for the chosen modules,
// #define RC_...(args) lines naming their functions, no-op defines for the modules left out, and a
// comment naming the configuration. Validates first (throws as validate() does).
inline constexpr const char* kRaycastConfigFile = "rc_config.glsl";
std::string generate_raycast_header(const RaycastConfig& config);
// {kRaycastConfigFile, generate_raycast_header(config)}: ready for ProgramSpec::generated.
GeneratedFile raycast_config_file(const RaycastConfig& config);

// The uber-shader's modules, generated from the same tables (raycast_uber.frag includes it): every module's
// file, the mode uniforms, and the RC_* placeholders defined as functions that pick a module per draw by those
// uniforms, one branch a row, so no mode can fall through to another's.
inline constexpr const char* kRaycastUberFile = "rc_uber.glsl";
std::string generate_raycast_uber_header();
GeneratedFile raycast_uber_file();  // {kRaycastUberFile, generate_raycast_uber_header()}

// The mode uniforms raycast_uber.frag reads (uGradientMode, uClassificationMode, uShadingMode,
// uCompositingMode, uEarlyTermination) for the effective configuration, so the uber-shader computes the
// image the specialised shader does and skips what it skips. Validates first.
std::vector<std::pair<std::string, int>> raycast_uber_uniforms(const RaycastConfig& config);

}  // namespace gsv
