// Lab 04: bump-mapped terrain from a real elevation model.
// Seed: Bailey, "Using GPU Shaders for Visualization, Part 2" (bump-mapped terrain).
// The heights are a float texture; one quad is drawn, and the fragment stage builds each pixel's normal
// from the heights around it (normal.glsl). Beside it, real geometry: an N x N grid displaced by the same
// heights, to see what the trick saves and where it shows.
#include "common/app/app.h"
#include "common/params/change_tracker.h"
#include "common/app/legend_probe.h"
#include "common/core/number_text.h"
#include "common/gl/gl.h"
#include "common/gl/gpu_mesh.h"
#include "common/gl/texture.h"
#include "common/scene/mesh_data.h"
#include "sweep_view.h"
#include "terrain_source.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace {

enum class Geometry { Bump, Mesh };
constexpr gsv::EnumName<Geometry> kGeometries[] = {{Geometry::Bump, "bump"}, {Geometry::Mesh, "mesh"}};
enum class Coloring { Levels, Plain };
constexpr gsv::EnumName<Coloring> kColorings[] = {{Coloring::Levels, "levels"}, {Coloring::Plain, "plain"}};

class TerrainLab final : public gsv::Lab, public lab04::SweepView {
public:
    gsv::LabInfo info() const override { return {"lab04", "Bump-mapped terrain"}; }

    void declare(gsv::Params& p) override {
        lab04::TerrainParams& t = terrain_params_;
        t.terrain = p.add_enum("terrain", lab04::RealTerrain::Jacksboro, lab04::kRealTerrains, gsv::kTerrainKindNames,
                               "real elevation models (data/terrain), or procedural ones whose exact normals are known");
        t.grid = p.add_int("grid", 256, 2, 2048, "samples per side of a procedural terrain")
                     .applies_when(t.terrain, {gsv::TerrainKind::Franke, gsv::TerrainKind::SinCos, gsv::TerrainKind::Flat});
        geometry_ = p.add_enum("geometry", Geometry::Bump, kGeometries, "one bump-mapped quad, or an N x N grid displaced by the heights")
                        .at_compile_time();
        mesh_n_ = p.add_int("mesh_n", 64, 2, 1024, "N, vertices per side of the displaced grid (geometry=mesh)")
                      .applies_when(geometry_, {Geometry::Mesh});
        p.add_float("delta", 1, 1e-5, 16, "finite-difference step, in samples (below about 1e-3 float32 cancels)")
            .with_step(0.5)
            .accuracy_knob({"16", "8", "4", "2", "1"});
        p.add_float("exaggeration", 3, 0, 100, "vertical exaggeration").with_step(0.5);
        mipmaps_ = p.add_effect("mipmaps", false, "mipmapped heights: zoomed out, far samples average instead of alias");
        p.add_int("mip_level", -1, -1, 10, "with mipmaps: -1 lets the hardware pick the level, k reads level k").applies_when(mipmaps_, true);
        t.heights8 = p.add_bool("heights8", false, "heights rounded to 256 levels, as an 8-bit texture would store them");
        p.add_choice("shading", "lit", {"lit", "slopes"},
                     "lit by the normal and coloured by height, or the slope itself as a colour (east red, north green)")
            .at_compile_time();
        coloring_ = p.add_enum("coloring", Coloring::Levels, kColorings, "sea, green, brown and snow by height, or one colour")
                        .at_compile_time();
        tree_line_ = p.add_float("tree_line", 0.35, 0, 1, "where green turns brown, as a fraction of the land's height range")
                         .applies_when(coloring_, {Coloring::Levels});
        snow_line_ = p.add_float("snow_line", 0.8, 0, 1, "where brown turns to snow").applies_when(coloring_, {Coloring::Levels});
        p.add_float("blend", 0.05, 0, 0.5, "half the width of each colour transition").with_step(0.01).applies_when(coloring_, {Coloring::Levels});
        p.add_vec3("light_direction", {-1.0f, 1.2f, -0.6f}, -10, 10, "towards the light (x east, y up, z south)");
        pan_east_ = p.add_float("pan_east", 0, -1, 1, "the point looked at, east of the centre, in model units").with_step(0.05);
        pan_south_ = p.add_float("pan_south", 0, -1, 1, "the point looked at, south of the centre").with_step(0.05);
        gsv::add_orbit_camera(p, 0, 60, 2.6f);
    }

    void setup(gsv::LabKit& kit) override {
        shade_ = &kit.program("terrain", {"terrain.vert", "terrain.frag"});
    }

    void render(gsv::LabKit& kit, const gsv::Frame& frame) override {
        update(kit);
        const auto& p = kit.params();
        const gsv::OrbitCamera camera = gsv::orbit_camera(p);
        gsv::Transforms t;
        t.model = glm::translate(glm::mat4(1.0f), -glm::vec3(pan_east_.get(), 0.0f, pan_south_.get()));
        t.view = camera.view();
        t.projection = camera.projection(frame.aspect());

        glEnable(GL_DEPTH_TEST);
        glClearColor(0.55f, 0.65f, 0.78f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        const gsv::ShaderProgram& program = kit.use(*shade_);
        kit.set_transforms(program, t);
        set_terrain_uniforms(program);
        grid_->draw();
    }

    // terrain.frag's lookups a fragment: the height, and normal.glsl's four for the differences east and north (the
    // seed's five); at most one fragment a pixel, where the terrain fills the frame.
    gsv::FrameWork frame_work(const gsv::Frame& frame) const override {
        gsv::FrameWork work;
        work.upper_bound = true;
        work.items.push_back({gsv::WorkKind::Fetch, gsv::ShaderPath::Fragment, "R32F 2D",
                              5.0 * frame.width * frame.height,
                              std::string("5 height lookups a fragment (1 + 4 for the normal)") +
                                  (mipmaps_.get() ? ", mipmapped: each trilinear, two levels" : "")});
        return work;
    }

    // What its sweep plan reads (sweep_view.h).
    const lab04::Terrain& terrain() const override { return *terrain_; }

    // The colours by height as color.glsl draws them, over the terrain's heights.
    std::optional<gsv::Legend> legend(gsv::LabKit& kit) override {
        if (coloring_.get() == Coloring::Plain) return std::nullopt;
        update(kit);
        const gsv::HeightField& f = terrain_->field;
        const auto set_uniforms = [&](const gsv::ShaderProgram& program) { set_terrain_uniforms(program); };
        gsv::Legend legend;
        legend.title = "height";
        legend.unit = "m";
        legend.min = f.min_height();
        legend.max = f.max_height();
        legend.note = "Unlit colours: the terrain shades them by its light.";
        if (!(legend.max > legend.min)) {  // a flat terrain: one height, one colour
            legend.specials.push_back({"every point: " + gsv::format_number(legend.min, 4) + " m", legend_probe_.colors(kit, {legend.min}, set_uniforms)[0]});
            return legend;
        }
        legend.ramp = legend_probe_.ramp(kit, legend.min, legend.max, 256, set_uniforms);
        legend.ticks = gsv::nice_ticks(legend.min, legend.max);
        // Where color.glsl centres its blends: fractions of the land's heights, sea level and up.
        const double land = std::max(legend.min, 0.0);
        legend.marks.push_back({land + tree_line_.get() * (legend.max - land), "tree line"});
        legend.marks.push_back({land + snow_line_.get() * (legend.max - land), "snow line"});
        if (legend.min < 0) legend.marks.push_back({0.0, "sea level"});
        return legend;
    }

private:
    void update(gsv::LabKit& kit) {
        const auto& p = kit.params();
        terrain_.update(p, [&] { return lab04::load_terrain(kit, terrain_params_); });
        heights_.update(p, [&] {
            const bool mipmaps = mipmaps_.get();
            gsv::Sampling sampling{mipmaps ? GLenum(GL_LINEAR_MIPMAP_LINEAR) : GLenum(GL_LINEAR), GL_LINEAR, GL_CLAMP_TO_EDGE};
            return gsv::Texture::create_2d(terrain_->field.width, terrain_->field.height, gsv::TexelFormat::R32F,
                                           terrain_->field.heights.data(), sampling);
        }, terrain_.version());
        grid_.update(p, [&] {
            const int n = geometry_.get() == Geometry::Mesh ? mesh_n_.get() : 2;
            return gsv::GpuMesh(gsv::make_grid(n), kit.profile());
        });
    }

    void set_terrain_uniforms(const gsv::ShaderProgram& program) const override {
        program.bind("uHeights", *heights_);
        lab04::set_placement(program, *terrain_);
    }

    lab04::TerrainParams terrain_params_;
    gsv::EnumParam<Geometry> geometry_;
    gsv::EnumParam<Coloring> coloring_;
    gsv::Param<int> mesh_n_;
    gsv::Param<bool> mipmaps_;
    gsv::Param<float> tree_line_, snow_line_, pan_east_, pan_south_;
    const gsv::ShaderLibrary::Entry* shade_ = nullptr;
    gsv::Tracked<gsv::GpuMesh> grid_;
    gsv::Tracked<lab04::Terrain> terrain_;
    gsv::Tracked<gsv::Texture> heights_;
    gsv::LegendProbe legend_probe_{"legend_probe.frag"};
};

}  // namespace

int main(int argc, char** argv) { return gsv::run_lab<TerrainLab>(argc, argv); }
