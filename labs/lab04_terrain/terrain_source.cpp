#include "terrain_source.h"

#include "common/shader/shader_program.h"

#include <algorithm>
#include <cmath>

namespace lab04 {
namespace {

constexpr double kProceduralExtentM = 10000;

void round_to_8_bits(gsv::HeightField& field) {
    const float low = field.min_height(), high = field.max_height();
    if (!(high > low)) return;
    for (float& h : field.heights) h = low + std::round((h - low) / (high - low) * 255.0f) / 255.0f * (high - low);
}

}  // namespace

Terrain load_terrain(const gsv::LabKit& kit, const TerrainParams& p) {
    const TerrainChoice choice = p.terrain.get();
    Terrain terrain;
    if (const auto real = choice.as<RealTerrain>()) {
        terrain.field = gsv::load_height_field(kit.assets().data_file(
            std::string("terrain/") + (*real == RealTerrain::Jacksboro ? "jacksboro_fault" : "topobathy") + ".height"));
    } else {
        gsv::ProceduralTerrain procedural;
        procedural.kind = *choice.as<gsv::TerrainKind>();
        procedural.extent_m = kProceduralExtentM;
        procedural.amplitude_m = procedural.kind == gsv::TerrainKind::SinCos ? 300 : 1000;
        terrain.field = gsv::make_procedural(procedural, p.grid.get(), p.grid.get());
        terrain.procedural = procedural;
    }
    if (p.heights8.get()) round_to_8_bits(terrain.field);
    terrain.low = terrain.field.min_height();
    terrain.high = terrain.field.max_height();
    return terrain;
}

void set_placement(const gsv::ShaderProgram& program, const Terrain& terrain) {
    const gsv::HeightField& f = terrain.field;
    const double east_m = f.width * f.dx_m, north_m = f.height * f.dy_m;
    const double units_per_metre = 2.0 / std::max(east_m, north_m);
    program.set("uSpacing", glm::vec2(static_cast<float>(f.dx_m), static_cast<float>(f.dy_m)));
    program.set("uGround", glm::vec2(static_cast<float>(east_m * units_per_metre), static_cast<float>(north_m * units_per_metre)));
    program.set("uUnitsPerMetre", static_cast<float>(units_per_metre));
    program.set("uMidHeight", 0.5f * (terrain.low + terrain.high));
    program.set("uHeightRange", glm::vec2(terrain.low, terrain.high));
}

}  // namespace lab04
