// Lab 01: GLSL basics and Gooch shading.
// Seed: Slusallek, "Programmable Shading in OpenGL"; Gooch et al., "A Non-Photorealistic Lighting
// Model for Automatic Technical Illustration" (SIGGRAPH 1998).
// The lesson is in the shaders (shade.vert, shade.frag, phong.glsl, gooch.glsl); this file declares
// the lab's parameters and draws one mesh.
#include "common/app/app.h"
#include "common/core/error.h"
#include "common/params/change_tracker.h"
#include "common/gl/gl.h"
#include "common/gl/gpu_mesh.h"
#include "common/image/image.h"
#include "common/scene/mesh_data.h"

#include "sweep_view.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>

namespace {

enum class Model { Sphere, Torus, Teapot, File };
constexpr gsv::EnumName<Model> kModels[] = {
    {Model::Sphere, "sphere"}, {Model::Torus, "torus"}, {Model::Teapot, "teapot"}, {Model::File, "file"}};
enum class Shading { Phong, Gooch, Normals };
constexpr gsv::EnumName<Shading> kShadings[] = {{Shading::Phong, "phong"}, {Shading::Gooch, "gooch"}, {Shading::Normals, "normals"}};
enum class ShadingRate { Vertex, Fragment };
constexpr gsv::EnumName<ShadingRate> kShadingRates[] = {{ShadingRate::Vertex, "vertex"}, {ShadingRate::Fragment, "fragment"}};

class GoochLab final : public gsv::Lab, public lab01::SweepView {
public:
    gsv::LabInfo info() const override { return {"lab01", "GLSL basics and Gooch shading"}; }

    void declare(gsv::Params& p) override {
        model_ = p.add_enum("model", Model::Sphere, kModels,
                            "the mesh: two procedural ones, the teapot from data/meshes, or any OBJ file (mesh_file)");
        mesh_file_ = p.add_file("mesh_file", "", "an OBJ file: triangles or polygons, with or without normals (model=file)")
                         .applies_when(model_, {Model::File});
        const auto shading = p.add_enum("shading", Shading::Gooch, kShadings,
                                        "the lighting model, or the eye-space normal as a colour (what L01-T1 computes, before any light)")
                                 .at_compile_time();
        shading_rate_ = p.add_enum("shading_rate", ShadingRate::Fragment, kShadingRates,
                                   "light each vertex and blend colours (Gouraud), or light each fragment").at_compile_time().series();
        mesh_resolution_ = p.add_int("mesh_resolution", 64, 3, 1024, "segments around the sphere or torus (half as many the other way)")
                               .accuracy_knob({"6", "8", "12", "16", "24", "32", "64", "128", "256", "512"});
        const auto specular = p.add_effect("specular", true, "the white Phong highlight");
        silhouette_ = p.add_effect("silhouette", false, "dark edges where the surface turns away from the eye");
        p.add_vec3("diffuse_color", {0.75f, 0.35f, 0.25f}, 0, 1, "k_d, the surface colour");
        p.add_float("blue", 0.55, 0, 1, "b in k_blue = (0, 0, b)").applies_when(shading, {Shading::Gooch});
        p.add_float("yellow", 0.45, 0, 1, "y in k_yellow = (y, y, 0)").applies_when(shading, {Shading::Gooch});
        p.add_float("alpha", 0.25, 0, 1, "share of k_d in the cool colour").applies_when(shading, {Shading::Gooch});
        p.add_float("beta", 0.5, 0, 1, "share of k_d in the warm colour").applies_when(shading, {Shading::Gooch});
        p.add_float("shininess", 32, 1, 256, "Phong exponent").with_step(4).applies_when(specular, true);
        p.add_float("specular_strength", 0.5, 0, 1, "highlight strength").applies_when(specular, true);
        p.add_float("edge_threshold", 0.25, 0, 1, "silhouette width, as a bound on |n.v|").applies_when(silhouette_, true);
        light_position_ = p.add_vec3("light_position", {-3.0f, 3.0f, 1.0f}, -20, 20, "the point light, in world space");
        scale_ = p.add_vec3("scale", {1.0f, 1.0f, 1.0f}, 0.1, 4, "model scale; unequal axes need the inverse-transpose for normals");
        cut_ = p.add_float("cut", 2, -1, 2, "cut the model open beyond x = cut, so its back faces show");
        gsv::add_orbit_camera(p, 30, 20, 3.4f);
    }

    void setup(gsv::LabKit& kit) override {
        shade_ = &kit.program("shade", {"shade.vert", "shade.frag"});
        teapot_ = gsv::load_obj(kit.assets().data_file("meshes/teapot.obj"));
        gsv::normalize_to_unit_sphere(teapot_);
        params_changed(kit);
    }

    // The mesh is remade only when the model or (for the procedural ones) its resolution changes.
    void params_changed(gsv::LabKit& kit) override {
        mesh_.update(kit.params(), [&] {
            const Model model = model_.get();
            if (model == Model::Teapot) {
                loaded_triangles_ = teapot_.triangle_count();
                return gsv::GpuMesh(teapot_, kit.profile());
            }
            if (model == Model::File) {
                const gsv::MeshData mesh = load_mesh_file(kit);
                loaded_triangles_ = mesh.triangle_count();
                return gsv::GpuMesh(mesh, kit.profile());
            }
            const glm::ivec2 segments = procedural_segments();
            if (model == Model::Sphere) return gsv::GpuMesh(gsv::make_uv_sphere(segments.x, segments.y), kit.profile());
            return gsv::GpuMesh(gsv::make_torus(segments.x, segments.y, 0.7f, 0.3f), kit.profile());
        });
    }

    // The sphere's or torus's segments: mesh_resolution around, half as many the other way (a sphere needs 2
    // stacks, a torus's tube 3).
    glm::ivec2 procedural_segments() const {
        const int n = mesh_resolution_.get();
        return {n, std::max(model_.get() == Model::Sphere ? 2 : 3, n / 2)};
    }

    void render(gsv::LabKit& kit, const gsv::Frame& frame) override {
        draw(kit, frame, *shade_, kBackground);
    }

    // Any OBJ, scaled into the unit sphere the camera frames; the reader names the file and line of a fault.
    gsv::MeshData load_mesh_file(gsv::LabKit& kit) const {
        const std::string typed = mesh_file_.get();
        if (typed.empty()) throw gsv::Error("model=file needs mesh_file=PATH, an OBJ file");
        gsv::MeshData mesh = gsv::load_obj(kit.assets().user_file(typed));
        gsv::normalize_to_unit_sphere(mesh);
        return mesh;
    }

    // The lesson is per-fragment shading of a model that covers part of the frame: at most one shaded fragment a
    // pixel (fill), the lighting a few dozen flops each. And the mesh's triangles, each sent twice (draw(): back
    // faces culled, then front faces), so each is drawn once and culled once: a fine mesh is bound by them, not by
    // its fill. The sphere's and torus's count follow from their segments; the teapot's and a file's are known once
    // loaded (not in `list`, which loads nothing).
    gsv::FrameWork frame_work(const gsv::Frame& frame) const override {
        gsv::FrameWork work;
        work.upper_bound = true;
        work.items.push_back({gsv::WorkKind::Fragments, gsv::ShaderPath::Fragment, "",
                              static_cast<double>(frame.width) * frame.height, "one shaded fragment a pixel at most"});
        const Model model = model_.get();
        const glm::ivec2 segments = procedural_segments();
        const std::size_t triangles = model == Model::Sphere ? gsv::uv_sphere_triangle_count(segments.x, segments.y)
                                      : model == Model::Torus ? gsv::torus_triangle_count(segments.x, segments.y)
                                                              : loaded_triangles_;
        if (triangles > 0)
            work.items.push_back({gsv::WorkKind::Triangles, gsv::ShaderPath::Fragment, "", 2.0 * static_cast<double>(triangles),
                                  "the mesh's " + std::to_string(triangles) + " triangles, sent twice (back faces culled, then front)"});
        return work;
    }

    // What its sweep plan reads (sweep_view.h).
    bool exact_sphere_applies() const override {
        const glm::vec3 scale = scale_.get();
        return model_.get() == Model::Sphere && cut_.get() >= 1.0 && !silhouette_.get() && scale.x == scale.y && scale.y == scale.z;
    }
    bool lights_each_fragment() const override { return shading_rate_.get() == ShadingRate::Fragment; }
    const gsv::ShaderLibrary::Entry& shade_program() const override { return *shade_; }
    glm::vec4 background() const override { return kBackground; }

    void draw(gsv::LabKit& kit, const gsv::Frame& frame, const gsv::ShaderLibrary::Entry& entry, glm::vec4 background) override {
        glClearColor(background.r, background.g, background.b, background.a);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        const gsv::ShaderProgram& program = kit.use(entry);
        set_view(kit, program, frame);
        glEnable(GL_DEPTH_TEST);
        // Front faces first, then back faces pushed back by a polygon offset. Along a silhouette a front and a back
        // triangle share an edge, and near it both cover a pixel at the same depth but for rounding: drawn in one pass,
        // a back face could win that tie, and its normal, flipped to face the eye (shade.frag), points to the other
        // side of the rim (on the default sphere, one warm pixel on the cool side). Offset, back faces still show
        // wherever nothing is in front of them (a cut-open model, the teapot from below), and never win a tie.
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        mesh_->draw();
        glCullFace(GL_FRONT);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 1.0f);
        mesh_->draw();
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_CULL_FACE);
    }

    gsv::Transforms set_view(gsv::LabKit& kit, const gsv::ShaderProgram& program, const gsv::Frame& frame) const override {
        const gsv::OrbitCamera camera = gsv::orbit_camera(kit.params());
        gsv::Transforms t;
        t.model = glm::scale(glm::mat4(1.0f), scale_.get());
        t.view = camera.view();
        t.projection = camera.projection(frame.aspect());
        kit.set_transforms(program, t);
        program.set("uLightEye", glm::vec3(t.view * glm::vec4(light_position_.get(), 1.0f)));
        return t;
    }

private:
    static constexpr glm::vec4 kBackground{0.32f, 0.33f, 0.36f, 1.0f};

    gsv::EnumParam<Model> model_;
    gsv::EnumParam<ShadingRate> shading_rate_;
    gsv::Param<std::string> mesh_file_;
    gsv::Param<int> mesh_resolution_;
    gsv::Param<bool> silhouette_;
    gsv::Param<glm::vec3> light_position_, scale_;
    gsv::Param<float> cut_;
    const gsv::ShaderLibrary::Entry* shade_ = nullptr;
    gsv::MeshData teapot_;
    std::size_t loaded_triangles_ = 0;  // the teapot's or the file's, once loaded
    gsv::Tracked<gsv::GpuMesh> mesh_;
};

}  // namespace

int main(int argc, char** argv) { return gsv::run_lab<GoochLab>(argc, argv); }
