#pragma once
// Where desktop GL and OpenGL ES part: each feature the kit uses that a profile may lack, with the first
// desktop and the first ES version that have it. One table, so a refusal names the feature and the
// version that has it the same way everywhere (exit 3), and the lab sheets' table is this one.
#include "common/gl/gl_version.h"

#include <string>

namespace gsv {

struct GlFeature {
    const char* name;
    GlVersion desktop;
    GlVersion es;
    // Where a shader can take a stand-in: the kit defines this (to 1) in every shader of a run that lacks the
    // feature, so the GLSL and the C++ (LabKit::allows) decide from the same row. Null: no stand-in, refuse.
    const char* missing_define = nullptr;
    // What a grading case names it by where it cannot be checked without it ("feature": "compute"); null: no case does.
    const char* key = nullptr;
};

namespace gl_feature {
// Below it lab 05 steps its particles by transform feedback instead (WebGL 2 is OpenGL ES 3.0): its C++ picks the
// program (LabKit::allows), so no shader needs a define for it.
inline constexpr GlFeature kCompute{"compute shaders and storage buffers", {4, 3}, {3, 1}, nullptr, "compute"};
inline constexpr GlFeature kBufferTextures{"buffer textures (samplerBuffer)", {3, 1}, {3, 2}, "GSV_NO_BUFFER_TEXTURES"};
inline constexpr GlFeature kFragmentPrimitiveId{"gl_PrimitiveID in a fragment shader", {3, 2}, {3, 2},
                                                "GSV_NO_PRIMITIVE_ID"};
// GLSL 4.00 and GLSL ES 3.20 index an array of samplers with any dynamically uniform expression; before
// them only a constant may index it (which is why texture arrays exist).
inline constexpr GlFeature kSamplerArrayIndexing{"an array of samplers indexed by a uniform", {4, 0}, {3, 2}};

inline constexpr const GlFeature* kAll[] = {&kCompute, &kBufferTextures, &kFragmentPrimitiveId, &kSamplerArrayIndexing};
}  // namespace gl_feature

// The feature a case file names by its key ("compute"); null where none has that key.
inline const GlFeature* gl_feature_keyed(const std::string& key) {
    for (const GlFeature* feature : gl_feature::kAll)
        if (feature->key && key == feature->key) return feature;
    return nullptr;
}

inline GlVersion first_version_with(const GlFeature& feature, Profile profile) {
    return profile == Profile::Es ? feature.es : feature.desktop;
}
inline bool allows(const GlFeature& feature, Profile profile, GlVersion version) {
    return !(version < first_version_with(feature, profile));
}
// "needs compute shaders and storage buffers, which OpenGL ES has from 3.1; this run holds to 3.0 (--gl 3.1 where
// the driver offers it)": the caller puts what needs it first.
inline std::string missing_feature_message(const GlFeature& feature, Profile profile, GlVersion version) {
    const GlVersion first = first_version_with(feature, profile);
    return std::string("needs ") + feature.name + ", which " + (profile == Profile::Es ? "OpenGL ES" : "OpenGL") +
           " has from " + first.str() + "; this run holds to " + version.str() + " (--gl " + first.str() +
           " where the driver offers it)";
}

}  // namespace gsv
