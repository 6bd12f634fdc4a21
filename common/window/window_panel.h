#pragma once
// The on-screen panel of window mode: every parameter, the frame time and the last shader error.
// Dear ImGui where the build found it (sliders), the window title otherwise (keys still work).
#include "common/app/params.h"
#include "common/gl/gl_version.h"
#include "common/image/legend.h"

#include <memory>
#include <optional>
#include <string>

struct GLFWwindow;

namespace gsv {

struct PanelState {
    Params& params;
    int& selected;           // the parameter the arrow keys move
    double frame_ms = 0;     // wall time between frames
    double render_ms = 0;    // lab render time, bracketed by glFinish
    std::string heading;     // "lab01 (solution)"
    std::string gl;          // renderer and version
    std::string status;      // last shader error or reload message
    std::optional<Legend> legend;  // what the colours stand for, where they are data (Lab::legend)
};

class WindowPanel {
public:
    virtual ~WindowPanel() = default;
    // Draws the panel over the frame; returns true when the user changed a parameter in it.
    virtual bool draw(PanelState& state) = 0;
    virtual bool wants_mouse() const { return false; }
    virtual bool wants_keyboard() const { return false; }
};

std::unique_ptr<WindowPanel> make_window_panel(GLFWwindow* window, GlVersion version);

}  // namespace gsv
