#pragma once
// A lab's legend in the window's ImGui panel, live: a horizontal colour bar with its ticks, named marks, the
// opacity curve of a transfer function above it, and the colours that stand for no value. Drawn with the current
// window's draw list where the panel's cursor is, as one more widget of the panel.
#include "common/image/legend.h"

namespace gsv {

// Call between ImGui::Begin and ImGui::End.
void draw_legend_imgui(const Legend& legend);

}  // namespace gsv
