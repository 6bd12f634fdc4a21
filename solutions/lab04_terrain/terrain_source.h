#pragma once
// Lab 04's support code, not part of the lesson: the terrain to draw, where it sits in the world, and the
// sweep's measurement of the shader's normals.
#include "common/app/app.h"
#include "common/gl/gpu_mesh.h"
#include "support/terrain/height_field.h"
#include "support/terrain/terrain_procedural.h"

#include <functional>
#include <optional>
#include <string>

namespace lab04 {

struct Terrain {
    gsv::HeightField field;                              // as uploaded (rounded to 8 bits with heights8=on)
    std::optional<gsv::ProceduralTerrain> procedural;    // set when the exact normals are known
};

// A real model from data/terrain (one line naming the file if it is missing or corrupt), or a procedural
// terrain on a grid x grid samples over 10 km.
Terrain load_terrain(gsv::LabKit& kit);

// The uniforms that place the terrain in the world: the larger side spans 2 model units, heights at the
// same scale (times the exaggeration), the middle height at y = 0; and the spacing and height range.
void set_placement(const gsv::ShaderProgram& program, const Terrain& terrain);

// The shader's normals (normal_probe.frag, one fragment per sample) against the exact normals of a
// procedural terrain or, for a real model, the normals of its full-resolution differences (delta 1): mean and
// largest angle in degrees; and the largest angle between the shader's normals and the same differences in
// double precision at the same delta (finite_difference_normal for a whole step), which only rounding should
// separate, until a step far below a sample makes float32 cancel.
gsv::SweepMetrics measure_normals(gsv::LabKit& kit, const Terrain& terrain, const gsv::ShaderLibrary::Entry& probe,
                                  const gsv::GpuMesh& quad, const std::function<void(const gsv::ShaderProgram&)>& set_uniforms);

}  // namespace lab04
