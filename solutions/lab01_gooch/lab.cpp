// Lab 01: GLSL basics and Gooch shading.
// Seed: Slusallek, "Programmable Shading in OpenGL"; Gooch et al., "A Non-Photorealistic Lighting
// Model for Automatic Technical Illustration" (SIGGRAPH 1998).
// The lesson is in the shaders (shade.vert, shade.frag, phong.glsl, gooch.glsl); this file declares
// the lab's parameters and draws one mesh.
#include "common/app/app.h"
#include "common/app/change_tracker.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/gl/gpu_mesh.h"
#include "common/image/image.h"
#include "common/scene/mesh_data.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace {

class GoochLab final : public gsv::Lab {
public:
    gsv::LabInfo info() const override { return {"lab01", "GLSL basics and Gooch shading"}; }

    void declare(gsv::Params& p) override {
        p.add_choice("model", "sphere", {"sphere", "torus", "teapot"}, "the mesh: two procedural ones, one loaded from data/meshes");
        p.add_choice("shading", "gooch", {"phong", "gooch"}, "the lighting model").at_compile_time();
        p.add_choice("shading_rate", "fragment", {"vertex", "fragment"},
                     "light each vertex and blend colours (Gouraud), or light each fragment").at_compile_time().series();
        p.add_int("mesh_resolution", 64, 3, 1024, "segments around the sphere or torus (half as many the other way)")
            .accuracy_knob({"6", "8", "12", "16", "24", "32", "64", "128", "256", "512"});
        p.add_effect("specular", true, "the white Phong highlight");
        p.add_effect("silhouette", false, "dark edges where the surface turns away from the eye");
        p.add_vec3("diffuse_color", {0.75f, 0.35f, 0.25f}, 0, 1, "k_d, the surface colour");
        p.add_float("blue", 0.55, 0, 1, "b in k_blue = (0, 0, b)");
        p.add_float("yellow", 0.45, 0, 1, "y in k_yellow = (y, y, 0)");
        p.add_float("alpha", 0.25, 0, 1, "share of k_d in the cool colour");
        p.add_float("beta", 0.5, 0, 1, "share of k_d in the warm colour");
        p.add_float("shininess", 32, 1, 256, "Phong exponent").with_step(4);
        p.add_float("specular_strength", 0.5, 0, 1, "highlight strength");
        p.add_float("edge_threshold", 0.25, 0, 1, "silhouette width, as a bound on |n.v|");
        p.add_vec3("light_position", {-3.0f, 3.0f, 1.0f}, -20, 20, "the point light, in world space");
        p.add_vec3("scale", {1.0f, 1.0f, 1.0f}, 0.1, 4, "model scale; unequal axes need the inverse-transpose for normals");
        p.add_float("cut", 2, -1, 2, "cut the model open beyond x = cut, so its back faces show");
        gsv::add_orbit_camera(p, 30, 20, 3.4f);
    }

    void setup(gsv::LabKit& kit) override {
        shade_ = &kit.program("shade", {"shade.vert", "shade.frag"});
        normal_error_ = &kit.program("normal_error", {"shade.vert", "normal_error.frag"});
        teapot_ = gsv::load_obj(kit.assets().data_file("meshes/teapot.obj"));
        gsv::normalize_to_unit_sphere(teapot_);
        params_changed(kit);
    }

    // The mesh is remade only when the model or (for the procedural ones) its resolution changes.
    void params_changed(gsv::LabKit& kit) override {
        mesh_.update(kit.params(), [&] {
            const auto& p = kit.params();
            const std::string model = p.get_choice("model");
            if (model == "teapot") return gsv::GpuMesh(teapot_, kit.profile());
            const int n = p.get_int("mesh_resolution");
            if (model == "sphere") return gsv::GpuMesh(gsv::make_uv_sphere(n, std::max(2, n / 2)), kit.profile());
            return gsv::GpuMesh(gsv::make_torus(n, std::max(3, n / 2), 0.7f, 0.3f), kit.profile());
        });
    }

    void render(gsv::LabKit& kit, const gsv::Frame& frame) override {
        draw(kit, frame, *shade_);
    }

    std::vector<std::string> sweep_reference() const override {
        return {"shading_rate=fragment", "mesh_resolution=1024"};
    }

    // The normal the shader lights with against the sphere's exact normal, over the covered pixels.
    gsv::SweepMetrics sweep_metrics(gsv::LabKit& kit, const gsv::Frame& frame) override {
        if (kit.params().get_choice("model") != "sphere") return {};
        gsv::Framebuffer target(frame.width, frame.height, gsv::ColorFormat::RGBA32F);
        target.bind();
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        draw(kit, frame, *normal_error_);
        const gsv::ImageF angles = target.read_rgba32f();
        double sum = 0, worst = 0;
        long covered = 0;
        for (int y = 0; y < angles.height; ++y)
            for (int x = 0; x < angles.width; ++x) {
                const float* texel = angles.at(x, y);
                if (texel[3] == 0.0f) continue;
                sum += texel[0];
                worst = std::max(worst, static_cast<double>(texel[0]));
                ++covered;
            }
        return {{"normal_err_mean_deg", covered ? sum / static_cast<double>(covered) : 0.0},
                {"normal_err_max_deg", worst}};
    }

private:
    void draw(gsv::LabKit& kit, const gsv::Frame& frame, const gsv::ShaderLibrary::Entry& entry) {
        const auto& p = kit.params();
        const gsv::OrbitCamera camera = gsv::orbit_camera(p);
        gsv::Transforms t;
        t.model = glm::scale(glm::mat4(1.0f), p.get_vec3("scale"));
        t.view = camera.view();
        t.projection = camera.projection(frame.aspect());

        glEnable(GL_DEPTH_TEST);
        glClearColor(0.32f, 0.33f, 0.36f, 1.0f);
        if (&entry == shade_) glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        const gsv::ShaderProgram& program = kit.use(entry);
        kit.set_transforms(program, t);
        program.set("uLightEye", glm::vec3(t.view * glm::vec4(p.get_vec3("light_position"), 1.0f)));
        mesh_->draw();
    }

    const gsv::ShaderLibrary::Entry* shade_ = nullptr;
    const gsv::ShaderLibrary::Entry* normal_error_ = nullptr;
    gsv::MeshData teapot_;
    gsv::Tracked<gsv::GpuMesh> mesh_;
};

}  // namespace

int main(int argc, char** argv) { return gsv::run_lab<GoochLab>(argc, argv); }
