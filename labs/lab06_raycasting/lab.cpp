// Lab 06: modular GPU volume raycasting, composed only of the modules a scene calls for.
// Seed: Meyer-Spradow, Ropinski, Mensmann, Hinrichs, "Interactive Design and Debugging of GPU-based Volume
// Visualizations" (GRAPP 2010), on the Voreen engine (Meyer-Spradow et al., IEEE CG&A 29(6), 2009).
// The picture comes from a small data-flow network (network.cpp, or a network file): a volume source, its
// proxy geometry, entry and exit points, the ray traversal and a canvas. The ray traversal is one shader
// skeleton (raycast.frag) whose placeholders are filled, at compile time, with only the modules chosen:
// gradient, classification, shading and compositing.
#include "common/app/app.h"
#include "common/params/change_tracker.h"
#include "common/app/legend_probe.h"
#include "common/core/error.h"
#include "common/gl/gl.h"
#include "image_processors.h"
#include "network.h"
#include "ray_traversal.h"
#include "sweep_view.h"
#include "support/network/network_file.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

class RaycastLab final : public gsv::Lab, public lab06::SweepView {
public:
    gsv::LabInfo info() const override { return {"lab06", "Modular GPU volume raycasting"}; }

    void declare(gsv::Params& p) override {
        network_file_ = p.add_file("network", "", "a network file, as typed or one in the lab folder (raycast.network, probe.network); "
                                                  "empty: built in code. Parameters the file sets win over these");
        probe_ = p.add_bool("probe", false, "an opaque sphere embedded in the volume: rays stop at it (network built in code)");
        // The processors declare their own parameters (sources.cpp, ray_traversal.cpp, ...); the lab offers those of
        // the network built in code, probe included, and each processor follows them (apply_params).
        const gsv::Network network = lab06::build_network(true);
        for (const auto& processor : network.processors())
            p.adopt(processor->name(), processor->describe(), processor->params());
        // Refined here, where the probe is a choice: the declarations are the processors'.
        p.param<glm::vec3>("probe_position").applies_when(probe_, true);
        p.param<float>("probe_radius").applies_when(probe_, true);
        p.param<std::string>("compositing").series();
        p.param<float>("samples_per_voxel").accuracy_knob({"0.25", "0.5", "1", "2", "4"});
        compare_shaders_ = p.add_bool("compare_shaders", false, "sweep: also time the uber-shader and the hand-written DVR")
                               .may_draw_the_same("it adds timings to a sweep; the picture is the chosen shader's");
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

    // The ray caster's loop, counted by the processor that runs it; nothing before a frame has read the volume.
    gsv::FrameWork frame_work(const gsv::Frame& frame) const override {
        const auto* raycaster = dynamic_cast<const lab06::RayTraversal*>(network_ ? network_->find("raycaster") : nullptr);
        return raycaster ? raycaster->frame_work(frame.width, frame.height) : gsv::FrameWork{};
    }

    // What its sweep plan reads (sweep_view.h).
    lab06::RayTraversal* raycaster() override {
        return dynamic_cast<lab06::RayTraversal*>(network_ ? network_->find("raycaster") : nullptr);
    }
    const lab06::FrameView& frame_view() const override { return view_; }
    bool compare_shaders() const override { return compare_shaders_.get(); }

    // The classification the ray caster ran with (its parameters: a network file's win over the lab's), sampled
    // from its own GLSL module and table: colour and opacity over the intensity.
    std::optional<gsv::Legend> legend(gsv::LabKit& kit) override {
        lab06::RayTraversal* traversal = raycaster();
        if (!traversal) return std::nullopt;
        using Config = gsv::RaycastConfig;
        const Config config = gsv::effective_config(lab06::raycast_modules(), traversal->config());
        const gsv::CompositingLegend says = gsv::compositing_legend(lab06::raycast_modules(), config.compositing);
        if (!says.shown) return std::nullopt;
        const bool table = config.classification == Config::Classification::TransferFunction;
        gsv::Legend legend;
        legend.title = table ? "intensity, transfer function " + traversal->transfer_function_name()
                             : "intensity, raw classification";
        legend.opacity = true;
        legend.ramp = (table ? tf_probe_ : raw_probe_).ramp(kit, 0, 1, 256, [&](const gsv::ShaderProgram& program) {
            if (table) program.bind("uTransferFunction", traversal->transfer_function());
        });
        legend.ticks = gsv::nice_ticks(0, 1);
        if (says.marks_iso_value) legend.marks.push_back({traversal->iso_value(), "iso value"});
        legend.note = says.note;
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
        const std::string file = network_file_.get();
        const std::filesystem::path path = file.empty() ? std::filesystem::path() : network_path(kit.assets(), file);
        std::error_code ec;
        const auto saved = file.empty() ? 0 : std::filesystem::last_write_time(path, ec).time_since_epoch().count();
        network_built_.run_if_changed(kit.params(), [&] { network_ = load_network(path); }, path.string(), saved);
    }

    std::unique_ptr<gsv::Network> load_network(const std::filesystem::path& path) {
        auto network = std::make_unique<gsv::Network>(network_file_.get().empty() ? lab06::build_network(probe_.get())
                                                                                   : gsv::read_network_file(path, registry_));
        lab06::set_view(*network, &view_);
        return network;
    }

    // Each processor's parameters follow the lab's of the same name, unless the network file set them.
    void apply_params(const gsv::Params& p) {
        for (const auto& processor : network_->processors())
            processor->params().follow(p, processor->name(), [&](const std::string& name) { return processor->is_set(name); });
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

    gsv::Param<std::string> network_file_;
    gsv::Param<bool> probe_, compare_shaders_;
    gsv::ProcessorRegistry registry_;
    std::unique_ptr<gsv::Network> network_;
    gsv::ChangeTracker network_built_;
    lab06::FrameView view_;
    std::string last_failure_;
    gsv::LegendProbe tf_probe_{"legend_tf.frag"}, raw_probe_{"legend_raw.frag"};
};

}  // namespace

int main(int argc, char** argv) { return gsv::run_lab<RaycastLab>(argc, argv); }
