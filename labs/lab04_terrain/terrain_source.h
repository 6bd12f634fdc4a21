#pragma once
// Lab 04's support code, not part of the lesson: the terrain to draw and where it sits in the world. (The sweep's
// measurement of the shader's normals is the instructor's: reference/lab04_terrain/.)
#include "common/app/app.h"
#include "support/terrain/height_field.h"
#include "support/terrain/terrain_procedural.h"

#include <optional>
#include <string>

namespace lab04 {

struct Terrain {
    gsv::HeightField field;                              // as uploaded (rounded to 8 bits with heights8=on)
    std::optional<gsv::ProceduralTerrain> procedural;    // set when the exact normals are known
    // The field's lowest and highest heights, found once when it is loaded: every frame places the terrain by them,
    // and scanning a million heights a frame was most of a frame in the browser (1.5 ms of lab 04's 2.6).
    float low = 0, high = 0;
};

// The real elevation models in data/terrain, then support/terrain's procedural ones (gsv::kTerrainKindNames).
enum class RealTerrain { Jacksboro, Topobathy };
inline constexpr gsv::EnumName<RealTerrain> kRealTerrains[] = {{RealTerrain::Jacksboro, "jacksboro"}, {RealTerrain::Topobathy, "topobathy"}};
using TerrainChoice = gsv::OneOf<RealTerrain, gsv::TerrainKind>;

// The lab's parameters a terrain is made from: declared by the lab (lab.cpp), which keeps them.
struct TerrainParams {
    gsv::EnumParam<TerrainChoice> terrain;
    gsv::Param<int> grid;
    gsv::Param<bool> heights8;
};

// A real model from data/terrain (one line naming the file if it is missing or corrupt), or a procedural
// terrain on a grid x grid samples over 10 km.
Terrain load_terrain(const gsv::LabKit& kit, const TerrainParams& p);

// The uniforms that place the terrain in the world: the larger side spans 2 model units, heights at the
// same scale (times the exaggeration), the middle height at y = 0; and the spacing and height range.
void set_placement(const gsv::ShaderProgram& program, const Terrain& terrain);

}  // namespace lab04
