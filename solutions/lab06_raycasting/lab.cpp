// Lab 06: modular GPU volume raycasting, composed only of the modules a scene calls for.
// Seed: Meyer-Spradow, Ropinski, Mensmann, Hinrichs, "Interactive Design and Debugging of GPU-based Volume
// Visualizations" (GRAPP 2010), on the Voreen engine (Meyer-Spradow et al., IEEE CG&A 29(6), 2009).
// The picture comes from a small data-flow network (network.cpp, or a network file): a volume source, its
// proxy geometry, entry and exit points, the ray traversal and a canvas. The ray traversal is one shader
// skeleton (raycast.frag) whose placeholders are filled, at compile time, with only the modules chosen:
// gradient, classification, shading and compositing.
#include "common/app/app.h"
#include "common/app/change_tracker.h"
#include "common/app/legend_probe.h"
#include "common/core/error.h"
#include "common/gl/gl.h"
#include "image_processors.h"
#include "network.h"
#include "ray_measure.h"
#include "ray_traversal.h"
#include "support/network/network_file.h"
#ifdef GSV_HAVE_REFERENCE
#include "reference/lab06_raycasting/hit_measure.h"  // the instructor's measurements (cmake/labs.cmake)
#endif

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace {

class RaycastLab final : public gsv::Lab {
public:
    gsv::LabInfo info() const override { return {"lab06", "Modular GPU volume raycasting"}; }

    void declare(gsv::Params& p) override {
        p.add_file("network", "", "a network file, as typed or one in the lab folder (raycast.network, probe.network); "
                                  "empty: built in code. Properties the file sets win over these parameters");
        p.add_bool("probe", false, "an opaque sphere embedded in the volume: rays stop at it (network built in code)");
        p.add_choice("volume", "marschner_lobb", {"marschner_lobb", "anatomical", "constant", "file"},
                     "the test signal (exact values known), the MRI head, a constant (zero gradient), or volume_file");
        p.add_file("volume_file", "", "a NIfTI-1 volume (.nii or .nii.gz), with volume=file").applies_when("volume", {"file"});
        p.add_int("ml_size", 41, 8, 256, "voxels per side of the Marschner-Lobb volume").applies_when("volume", {"marschner_lobb"});
        p.add_choice("compositing", "dvr", {"dvr", "mip", "iso", "fhp"},
                     "direct volume rendering, maximum intensity, isosurface, first hit").series();
        p.add_choice("gradient", "central", {"none", "forward", "central", "precomputed"}, "how normals are estimated");
        p.add_choice("classification", "tf", {"raw", "tf"}, "intensity as opacity, or the transfer function");
        p.add_choice("shading", "phong", {"none", "phong"}, "Phong needs a gradient");
        p.add_choice("shader", "specialised", {"specialised", "uber", "handwritten"},
                     "only the chosen modules compiled; all of them chosen by uniforms; DVR written by hand");
        p.add_choice("transfer_function", "bands", {"grey", "bands", "tissue"}, "the 1D transfer function");
        p.add_float("samples_per_voxel", 1, 0.05, 32, "samples along a ray per voxel (of the largest side)")
            .with_step(0.25)
            .accuracy_knob({"0.25", "0.5", "1", "2", "4"});
        p.add_bool("opacity_correction", true, "alpha' = 1 - (1 - alpha)^(step / voxel): the image keeps its opacity as the step changes");
        p.add_float("early_ray_threshold", 0.95, 0, 1, "DVR stops a ray once it is this opaque (1: never)").with_step(0.01);
        p.add_float("iso_value", 0.5, 0, 1, "the isosurface's value").with_step(0.01).applies_when("compositing", {"iso"});
        p.add_float("ambient", 0.25, 0, 1, "Phong k_a");
        p.add_float("diffuse", 0.7, 0, 1, "Phong k_d");
        p.add_float("specular", 0.3, 0, 1, "Phong k_s");
        p.add_float("shininess", 24, 1, 256, "Phong exponent").with_step(4);
        p.add_vec3("clip_normal", {0.0f, 0.0f, 0.0f}, -1, 1, "a clipping plane's normal in texture space (0,0,0: none)");
        p.add_float("clip_offset", 0, -1, 1, "keeps dot(n, t - centre) <= offset |n|").with_step(0.05);
        p.add_vec3("probe_position", {0.3f, -0.2f, 0.4f}, -1.5, 1.5, "the probe's centre (model space, the box's largest side 2)").applies_when("probe", {"on"});
        p.add_float("probe_radius", 0.25, 0.02, 1, "the probe's radius (model units)").with_step(0.02).applies_when("probe", {"on"});
        p.add_vec3("background", {0.08f, 0.09f, 0.12f}, 0, 1, "the canvas behind everything");
        p.add_bool("compare_shaders", false, "sweep: also time the uber-shader and the hand-written DVR");
        gsv::add_orbit_camera(p, 30, 25, framing_distance(), 0.1f);  // down to 0.1: inside the volume
    }

    void setup(gsv::LabKit&) override { registry_ = lab06::make_registry(); }

    void render(gsv::LabKit& kit, const gsv::Frame& frame) override {
        GLint target = 0;
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
        update_network(kit);
        const gsv::Params& p = kit.params();
        const gsv::OrbitCamera camera = gsv::orbit_camera(p);
        view_.kit = &kit;
        view_.width = frame.width;
        view_.height = frame.height;
        view_.view = camera.view();
        view_.projection = camera.projection(frame.aspect());
        view_.eye = camera.eye();
        view_.forward = glm::normalize(-camera.eye());  // the orbit camera looks at the origin
        view_.near_distance = near_distance(view_.projection);
        apply_params(p);
        const gsv::RunReport report = network_->run();

        glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
        glViewport(0, 0, frame.width, frame.height);
        if (!report.ok()) {
            const std::string failure = first_failure(report);
            // Headless, a failure ends the run. In a window, a new one goes to the status line (and the
            // parameters go back); the same one again (a shader broken on disk) keeps the last picture.
            if (!frame.interactive || failure != last_failure_) {
                last_failure_ = failure;
                throw gsv::Error(failure);
            }
        } else {
            last_failure_.clear();
        }
        const auto* canvas = dynamic_cast<const lab06::Canvas*>(network_->find("canvas"));
        if (!canvas || !canvas->image()) throw gsv::Error("the network has no Canvas processor named 'canvas' to show");
        const gsv::Framebuffer& image = *canvas->image();
        glBindFramebuffer(GL_READ_FRAMEBUFFER, image.id());
        glBlitFramebuffer(0, 0, image.width(), image.height(), 0, 0, frame.width, frame.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
    }

    std::vector<std::string> sweep_reference() const override { return {"samples_per_voxel=16"}; }
    std::vector<std::string> sweep_reference_refinement() const override { return {"samples_per_voxel=32"}; }
    std::string sweep_reference_name() const override {
#ifdef GSV_HAVE_REFERENCE
        return "images: the same compositing at 16 samples per voxel; isosurface hits (iso_err): the exact crossing of the "
               "Marschner-Lobb signal along each ray, in double";
#else
        return "images: the same compositing at 16 samples per voxel";
#endif
    }
    bool sweep_reference_per_series() const override { return true; }

    gsv::SweepMetrics sweep_metrics(gsv::LabKit& kit, const gsv::Frame&) override {
        auto* raycaster = dynamic_cast<lab06::RayTraversal*>(network_ ? network_->find("raycaster") : nullptr);
        if (!raycaster) return {};
        gsv::SweepMetrics metrics;
#ifdef GSV_HAVE_REFERENCE
        metrics = lab06::measure_hits(kit, *raycaster, view_);  // against the instructor's exact hits (reference/)
#endif
        if (kit.params().get_bool("compare_shaders")) {
            const gsv::SweepMetrics times = lab06::compare_shaders(*raycaster);
            metrics.insert(metrics.end(), times.begin(), times.end());
        }
        return metrics;
    }

    // The classification the ray caster ran with (its properties: a network file's win over the parameters), sampled
    // from its own GLSL module and table: colour and opacity over the intensity.
    std::optional<gsv::Legend> legend(gsv::LabKit& kit) override {
        auto* raycaster = dynamic_cast<lab06::RayTraversal*>(network_ ? network_->find("raycaster") : nullptr);
        if (!raycaster) return std::nullopt;
        using Config = gsv::RaycastConfig;
        const Config config = gsv::effective_config(raycaster->config());
        if (config.compositing == Config::Compositing::FirstHit) return std::nullopt;  // its colours are positions
        const bool table = config.classification == Config::Classification::TransferFunction;
        gsv::Legend legend;
        legend.title = table ? "intensity, transfer function " + raycaster->property("transfer_function")
                             : "intensity, raw classification";
        legend.opacity = true;
        legend.ramp = (table ? tf_probe_ : raw_probe_).ramp(kit, 0, 1, 256, [&](const gsv::ShaderProgram& program) {
            if (table) program.bind("uTransferFunction", raycaster->transfer_function());
        });
        legend.ticks = gsv::nice_ticks(0, 1);
        switch (config.compositing) {
        case Config::Compositing::Dvr:
            legend.note = "Opacity per voxel-long step; each sample is blended front to back.";
            break;
        case Config::Compositing::Mip:
            legend.note = "MIP: each pixel shows the largest intensity on its ray, its colour times its opacity.";
            break;
        default:
            legend.marks.push_back({std::stod(raycaster->property("iso_value")), "iso value"});
            legend.note = "Isosurface: the colour at the iso value, shaded, opaque.";
            break;
        }
        return legend;
    }

    std::vector<std::filesystem::path> write_debug_images(gsv::LabKit& kit, const std::filesystem::path& folder) override {
        if (!network_) return {};
        return lab06::write_port_images(kit, *network_, folder);
    }
    std::vector<gsv::InspectStage> inspect_stages() const override {
        return network_ ? lab06::inspect_stages(*network_) : std::vector<gsv::InspectStage>{};
    }
    std::optional<gsv::Image> inspect_image(gsv::LabKit& kit, const std::string& name) override {
        return network_ ? lab06::inspect_image(kit, *network_, name) : std::nullopt;
    }

private:
    // The network file, or the network built in code: rebuilt when either choice changes, and when the file is
    // saved (its time is a key), as a shader reloads.
    void update_network(gsv::LabKit& kit) {
        const std::string file = kit.params().get_file("network");
        const std::filesystem::path path = file.empty() ? std::filesystem::path() : network_path(kit.assets(), file);
        std::error_code ec;
        const auto saved = file.empty() ? 0 : std::filesystem::last_write_time(path, ec).time_since_epoch().count();
        network_built_.run_if_changed(kit.params(), [&] { network_ = load_network(kit.params(), path); }, path.string(), saved);
    }

    std::unique_ptr<gsv::Network> load_network(const gsv::Params& p, const std::filesystem::path& path) {
        auto network = std::make_unique<gsv::Network>(p.get_file("network").empty() ? lab06::build_network(p.get_bool("probe"))
                                                                                     : gsv::read_network_file(path, registry_));
        file_set_.clear();
        for (const auto& processor : network->processors())
            for (const auto& property : processor->properties())
                if (property.set) file_set_.insert(processor->name() + "." + property.name);
        lab06::set_view(*network, &view_);
        return network;
    }

    // Every property named like a parameter follows it, unless the network file set it.
    void apply_params(const gsv::Params& p) {
        std::set<std::string> names;
        for (const auto& spec : p.specs()) names.insert(spec.name);
        for (const auto& processor : network_->processors())
            for (const auto& property : processor->properties()) {
                if (!names.count(property.name) || file_set_.count(processor->name() + "." + property.name)) continue;
                const std::string value = p.get_text(property.name);
                if (value != property.value) processor->set_property(property.name, value);
            }
    }

    // As typed (from the working directory, then data/), or else one of the lab's own (raycast.network).
    static std::filesystem::path network_path(const gsv::Assets& assets, const std::string& typed) {
        std::error_code ec;
        if (std::filesystem::path(typed).is_relative() && std::filesystem::is_regular_file(assets.lab_dir() / typed, ec) &&
            !std::filesystem::exists(typed, ec))
            return assets.lab_dir() / typed;
        return assets.user_file(typed);
    }

    // Where the camera sees any volume whole, from any side: every box's largest side is 2 (VolumeBox), so the cube's
    // bounding sphere, of radius sqrt 3, holds them all, and from this distance that sphere just fills the field of
    // view's height.
    static float framing_distance() {
        const double half_fov = glm::radians(static_cast<double>(gsv::OrbitCamera{}.fov_degrees)) / 2.0;
        return static_cast<float>(std::sqrt(3.0) / std::sin(half_fov));
    }

    static float near_distance(const glm::mat4& projection) {
        // glm::perspective: P[2][2] = -(f + n) / (f - n), P[3][2] = -2 f n / (f - n), so n = P[3][2] / (P[2][2] - 1).
        return projection[3][2] / (projection[2][2] - 1.0f);
    }

    static std::string first_failure(const gsv::RunReport& report) {
        for (const auto& run : report.processors)
            if (run.state == gsv::RunState::Failed) return run.processor + ": " + run.error;
        return report.text();
    }

    gsv::ProcessorRegistry registry_;
    std::unique_ptr<gsv::Network> network_;
    gsv::ChangeTracker network_built_;
    std::set<std::string> file_set_;
    lab06::FrameView view_;
    std::string last_failure_;
    gsv::LegendProbe tf_probe_{"legend_tf.frag"}, raw_probe_{"legend_raw.frag"};
};

}  // namespace

int main(int argc, char** argv) { return gsv::run_lab<RaycastLab>(argc, argv); }
