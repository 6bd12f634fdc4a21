#pragma once
// Lab 06's network: the processors registered for network files, the default network built in code
// (the same as raycast.network, or probe.network with the probe), and writing every port's image.
#include "common/app/app.h"
#include "lab_processor.h"
#include "support/network/processor_network.h"
#include "support/network/processor_registry.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lab06 {

gsv::ProcessorRegistry make_registry();

// source -> proxy -> entry_exit -> raycaster -> canvas; with `probe`, a sphere drawn into the entry and exit
// points (rays stop at it) and rendered into the canvas behind the volume.
gsv::Network build_network(bool probe);

// Hands every processor the frame it draws. Throws gsv::Error for a processor of a type not from this lab.
void set_view(gsv::Network& network, const FrameView* view);

// Visual debugging: for every image output, <processor>.<port>.png (the colour: entry and exit points are
// texture coordinates as RGB), <processor>.<port>.alpha.png and <processor>.<port>.depth.png (alpha and
// depth as pseudo-colour; depth stretched over the range the image covers). Returns the files written.
std::vector<std::filesystem::path> write_port_images(gsv::LabKit& kit, const gsv::Network& network,
                                                     const std::filesystem::path& folder);
// The same live, for the window's inspector: each processor with how its last run went and its images'
// names ("raycaster.image", "raycaster.image alpha", "raycaster.image depth"), and one of them read back now.
std::vector<gsv::InspectStage> inspect_stages(const gsv::Network& network);
std::optional<gsv::Image> inspect_image(gsv::LabKit& kit, const gsv::Network& network, const std::string& name);

}  // namespace lab06
