// Lab 06: the specialised ray caster. rc_config.glsl is not a file: the C++ side generates it for the
// chosen configuration (gsv::generate_raycast_header) and hands it to the preprocessor
// (ProgramSpec::generated). It includes only the chosen modules and defines the skeleton's RC_*
// placeholders as their functions, so MIP, for one, compiles no gradient and no shading at all.
#include "rc_config.glsl"
#include "raycast_skeleton.glsl"
