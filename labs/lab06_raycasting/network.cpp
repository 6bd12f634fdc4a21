#include "network.h"

#include "common/core/error.h"
#include "common/image/image.h"
#include "entry_exit.h"
#include "image_processors.h"
#include "ray_traversal.h"
#include "sources.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lab06 {
namespace {

enum class PortView { Color, Alpha, Depth };

// A perceptually ordered ramp (dark blue, teal, green, yellow) for one scalar in [0, 1].
std::array<std::uint8_t, 4> pseudo_color(float x) {
    static const float ramp[5][3] = {{0.27f, 0.00f, 0.33f}, {0.23f, 0.32f, 0.55f}, {0.13f, 0.57f, 0.55f},
                                     {0.37f, 0.79f, 0.38f}, {0.99f, 0.91f, 0.15f}};
    const float t = std::clamp(x, 0.0f, 1.0f) * 4.0f;
    const int i = std::min(static_cast<int>(t), 3);
    const float w = t - static_cast<float>(i);
    std::array<std::uint8_t, 4> out{0, 0, 0, 255};
    for (int c = 0; c < 3; ++c)
        out[c] = static_cast<std::uint8_t>(std::lround(255.0f * (ramp[i][c] + w * (ramp[i + 1][c] - ramp[i][c]))));
    return out;
}

gsv::Image scalar_image(int width, int height, const std::vector<float>& values, float lo, float hi, const std::vector<bool>& shown) {
    gsv::Image image(width, height);
    for (std::size_t i = 0; i < values.size(); ++i) {
        const auto c = shown[i] ? pseudo_color(hi > lo ? (values[i] - lo) / (hi - lo) : 0.0f)
                                : std::array<std::uint8_t, 4>{0, 0, 0, 255};
        std::copy(c.begin(), c.end(), image.rgba.begin() + 4 * i);
    }
    return image;
}

// Alpha as it is; depth, which crowds near 1 under a perspective projection, stretched over what the image covers.
gsv::Image port_view(gsv::LabKit& kit, const ImageData& target, PortView view) {
    const gsv::ImageF color = target.read_rgba32f();
    if (view == PortView::Color) return gsv::to_rgba8(color);
    const std::size_t n = static_cast<std::size_t>(target.width()) * target.height();
    if (view == PortView::Alpha) {
        std::vector<float> alpha(n);
        for (std::size_t i = 0; i < n; ++i) alpha[i] = color.rgba[4 * i + 3];
        return scalar_image(target.width(), target.height(), alpha, 0.0f, 1.0f, std::vector<bool>(n, true));
    }
    const std::vector<float> depth = kit.read_depth(target);
    std::vector<bool> covered(n);
    float lo = 1.0f, hi = 0.0f;
    for (std::size_t i = 0; i < n; ++i) {
        covered[i] = depth[i] < 1.0f;
        if (covered[i]) {
            lo = std::min(lo, depth[i]);
            hi = std::max(hi, depth[i]);
        }
    }
    return scalar_image(target.width(), target.height(), depth, lo, hi, covered);
}

void write_image_port(gsv::LabKit& kit, const ImageData& target, const std::filesystem::path& file,
                      std::vector<std::filesystem::path>& written) {
    std::filesystem::path stem = file;
    stem.replace_extension();
    for (const auto& [view, name] : {std::pair{PortView::Color, file.string()}, std::pair{PortView::Alpha, stem.string() + ".alpha.png"},
                                     std::pair{PortView::Depth, stem.string() + ".depth.png"}}) {
        gsv::write_png(name, port_view(kit, target, view));
        written.push_back(name);
    }
}

}  // namespace

gsv::ProcessorRegistry make_registry() {
    gsv::ProcessorRegistry registry;
    registry.add<VolumeSource>();
    registry.add<ProxySource>();
    registry.add<ProbeSource>();
    registry.add<EntryExitPoints>();
    registry.add<RayTraversal>();
    registry.add<GeometryRenderer>();
    registry.add<Canvas>();
    return registry;
}

gsv::Network build_network(bool probe) {
    gsv::Network n;
    n.add<VolumeSource>("source");
    n.add<ProxySource>("proxy");
    if (probe) {
        n.add<ProbeSource>("probe");
        n.add<GeometryRenderer>("probe_renderer");
    }
    n.add<EntryExitPoints>("entry_exit");
    n.add<RayTraversal>("raycaster");
    n.add<Canvas>("canvas");
    n.connect("source.volume", "proxy.volume");
    n.connect("proxy.geometry", "entry_exit.proxy");
    if (probe) {
        n.connect("source.volume", "probe.volume");
        n.connect("probe.geometry", "entry_exit.occluder");
        n.connect("probe.geometry", "probe_renderer.geometry");
    }
    n.connect("source.volume", "raycaster.volume");
    n.connect("entry_exit.entry", "raycaster.entry");
    n.connect("entry_exit.exit", "raycaster.exit");
    n.connect("raycaster.image", "canvas.image");
    if (probe) n.connect("probe_renderer.image", "canvas.geometry");
    return n;
}

void set_view(gsv::Network& network, const FrameView* view) {
    for (const auto& p : network.processors()) {
        auto* lab_processor = dynamic_cast<LabProcessor*>(p.get());
        if (!lab_processor) throw gsv::Error(p->describe() + " is not one of lab 06's processors");
        lab_processor->set_view(view);
    }
}

std::vector<gsv::InspectStage> inspect_stages(const gsv::Network& network) {
    std::vector<gsv::InspectStage> stages;
    for (const auto& processor : network.processors()) {
        gsv::InspectStage stage{processor->name(), processor->error(), {}};
        if (processor->state() == gsv::RunState::Pending) stage.error = "not run yet";
        for (const auto& port : processor->outputs())
            if (port.type == gsv::PortType::Image)
                for (const char* view : {"", " alpha", " depth"}) stage.images.push_back(processor->name() + "." + port.name + view);
        stages.push_back(std::move(stage));
    }
    return stages;
}

std::optional<gsv::Image> inspect_image(gsv::LabKit& kit, const gsv::Network& network, const std::string& name) {
    const auto dot = name.find('.'), space = name.find(' ');
    const gsv::Processor* processor = network.find(name.substr(0, dot));
    const gsv::Port* port = processor && dot != std::string::npos ? processor->find_output(name.substr(dot + 1, space - dot - 1)) : nullptr;
    const auto target = port ? port->data.as<ImageData>() : nullptr;
    if (!target || processor->state() != gsv::RunState::Ran) return std::nullopt;
    const std::string view = space == std::string::npos ? "" : name.substr(space + 1);
    return port_view(kit, *target, view == "alpha" ? PortView::Alpha : view == "depth" ? PortView::Depth : PortView::Color);
}

std::vector<std::filesystem::path> write_port_images(gsv::LabKit& kit, const gsv::Network& network,
                                                     const std::filesystem::path& folder) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw gsv::Error("cannot create '" + folder.string() + "': " + ec.message());
    std::vector<std::filesystem::path> written;
    network.write_port_images(folder, [&](const gsv::Processor&, const gsv::Port& port, const std::filesystem::path& file) {
        if (auto target = port.data.as<ImageData>()) write_image_port(kit, *target, file, written);
    });
    return written;
}

}  // namespace lab06
