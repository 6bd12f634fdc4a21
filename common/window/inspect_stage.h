#pragma once
// Visual debugging, live (Voreen's port inspector): a stage of a lab's pipeline (lab 06: a processor of its
// network), how its last run went, and the images it can show in the window.
#include <string>
#include <vector>

namespace gsv {

struct InspectStage {
    std::string name;                 // "raycaster"
    std::string error;                // why it failed or did not run; empty when it ran
    std::vector<std::string> images;  // "raycaster.image", "raycaster.image alpha", "raycaster.image depth"
};

}  // namespace gsv
