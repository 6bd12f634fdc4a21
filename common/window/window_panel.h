#pragma once
// The on-screen panel of window mode: every parameter, the frame time and the last shader error.
// Dear ImGui where the build found it (sliders, docked beside the picture), the window title otherwise (keys still
// work).
#include "common/window/inspect_stage.h"
#include "common/params/params.h"
#include "common/gl/gl_version.h"
#include "common/image/legend.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace gsv {

struct PanelState {
    Params& params;
    int& selected;           // the parameter the arrow keys move
    double frame_ms = 0;     // wall time between frames
    double render_ms = 0;    // lab render time, bracketed by glFinish
    std::string heading;     // "lab01 (solution)"
    std::string gl;          // version and renderer: "OpenGL ES 3.0 on llvmpipe"
    std::string status;      // last shader error or reload message
    std::string view;        // what the picture shows, where not the lab's own render ("reference", "difference x4")
    std::vector<InspectStage> stages;  // the lab's pipeline, for visual debugging (none: no inspector)
    std::string inspected;             // the stage image shown in place of the picture; empty: the picture
    std::optional<Legend> legend;      // what the colours stand for, where they are data (Lab::legend)
    // The render time against this device's ceilings ("41% of this device's texture (fragment) ceiling"); empty where
    // they are unknown (gsv-ceilings has not measured them) or the lab states no work for the frame.
    std::string ceiling{};
};

// Where the panel goes: a column of the window, in window coordinates (GLFW's screen units).
struct PanelPlacement {
    float x = 0, width = 0, height = 0;
};

class WindowPanel {
public:
    virtual ~WindowPanel() = default;
    // The column the panel docks in beside the picture, in window coordinates; 0: it takes no room (the title).
    virtual int width() const { return 0; }
    // Draws the panel; returns true when the user changed a parameter in it.
    virtual bool draw(PanelState& state, const PanelPlacement& placement) = 0;
    virtual bool wants_mouse() const { return false; }
    virtual bool wants_keyboard() const { return false; }
};

std::unique_ptr<WindowPanel> make_window_panel(GLFWwindow* window, Profile profile, GlVersion version);
// The panel's column at a content scale of 1, before a window exists to measure: the window opens this much wider.
int default_panel_width();

}  // namespace gsv
