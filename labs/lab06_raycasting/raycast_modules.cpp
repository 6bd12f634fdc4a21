#include "raycast_modules.h"

namespace lab06 {

const gsv::RaycastModules& raycast_modules() {
    // Each table's rows in its RaycastConfig enum's order: {name, GLSL file, function}; a row with neither file nor
    // function leaves the module out.
    static const gsv::RaycastModules modules(
        {
            {"none", "", ""},
            {"forward", "gradient_forward.glsl", "rcGradientForward"},
            {"central", "gradient_central.glsl", "rcGradientCentral"},
            {"precomputed", "gradient_precomputed.glsl", "rcGradientPrecomputed"},
        },
        {
            {"raw", "classify_raw.glsl", "rcClassifyRaw"},
            {"tf", "classify_tf.glsl", "rcClassifyTf"},
        },
        {
            {"none", "", ""},
            {"phong", "shade_phong.glsl", "rcShadePhong"},
        },
        // {{name, file, X of rcStartX...}, description, shaded, optional termination, {legend shown, note, iso mark}}
        {
            {{"dvr", "composite_dvr.glsl", "Dvr"}, "direct volume rendering", true, true,
             {true, "Opacity per voxel-long step; each sample is blended front to back.", false}},
            {{"mip", "composite_mip.glsl", "Mip"}, "maximum intensity", false, false,
             {true, "MIP: each pixel shows the largest intensity on its ray, its colour times its opacity.", false}},
            {{"iso", "composite_iso.glsl", "Iso"}, "isosurface", true, false,
             {true, "Isosurface: the colour at the iso value, shaded, opaque.", true}},
            {{"fhp", "composite_fhp.glsl", "Fhp"}, "first hit", false, false, {false, "", false}},  // its colours are positions
        });
    return modules;
}

}  // namespace lab06
