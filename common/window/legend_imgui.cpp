#include "common/window/legend_imgui.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace gsv {
namespace {

ImU32 to_imgui(const LegendColor& c) { return IM_COL32(to_level(c[0]), to_level(c[1]), to_level(c[2]), 255); }

}  // namespace

void draw_legend_imgui(const Legend& legend) {
    ImGui::TextUnformatted(legend.heading().c_str());
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float line = ImGui::GetTextLineHeight();
    const float width = std::max(ImGui::GetContentRegionAvail().x, 12 * line);
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text), frame = IM_COL32(120, 120, 128, 255);
    const ImU32 mark_color = IM_COL32(255, 214, 110, 255);

    if (!legend.ramp.empty() && legend.max > legend.min) {
        auto x_of = [&](float x0, double value) {
            return x0 + static_cast<float>((value - legend.min) / (legend.max - legend.min)) * width;
        };
        const int columns = std::max(1, static_cast<int>(width));
        auto value_of = [&](int column) { return legend.min + (column + 0.5) / columns * (legend.max - legend.min); };
        if (legend.opacity) {
            // The opacity over the value, above the bar: where the volume is transparent, its colour is not seen.
            const ImVec2 p = ImGui::GetCursorScreenPos();
            const float h = 2.2f * line;
            draw->AddRectFilled(p, ImVec2(p.x + width, p.y + h), IM_COL32(46, 46, 52, 255));
            for (int i = 0; i < columns; ++i) {
                const LegendColor c = legend.color_at(value_of(i));
                const float top = p.y + h * (1.0f - std::clamp(c[3], 0.0f, 1.0f));
                draw->AddRectFilled(ImVec2(p.x + i, top), ImVec2(p.x + i + 1, p.y + h), to_imgui(c));
                draw->AddRectFilled(ImVec2(p.x + i, top - 1), ImVec2(p.x + i + 1, top + 1), text);
            }
            draw->AddText(ImVec2(p.x + 2, p.y), IM_COL32(200, 200, 205, 255), "opacity");
            ImGui::Dummy(ImVec2(width, h + 2));
        }
        const ImVec2 p = ImGui::GetCursorScreenPos();
        const float bar_h = 1.1f * line;
        for (int i = 0; i < columns; ++i)
            draw->AddRectFilled(ImVec2(p.x + i, p.y), ImVec2(p.x + i + 1, p.y + bar_h), to_imgui(legend.color_at(value_of(i))));
        draw->AddRect(ImVec2(p.x - 1, p.y - 1), ImVec2(p.x + width + 1, p.y + bar_h + 1), frame);
        for (const LegendMark& m : legend.marks) {
            if (m.value < legend.min || m.value > legend.max) continue;
            const float x = x_of(p.x, m.value);
            draw->AddLine(ImVec2(x, p.y - 2), ImVec2(x, p.y + bar_h + 2), IM_COL32(0, 0, 0, 255), 3.0f);
            draw->AddLine(ImVec2(x, p.y - 2), ImVec2(x, p.y + bar_h + 2), mark_color, 1.0f);
        }
        // Tick labels under the bar, centred on their value but kept inside it, each after the last one's end.
        const double spacing = tick_spacing(legend.ticks);
        float free_from = p.x - width;
        for (double t : legend.ticks) {
            if (t < legend.min || t > legend.max) continue;
            const float x = x_of(p.x, t);
            draw->AddLine(ImVec2(x, p.y + bar_h), ImVec2(x, p.y + bar_h + 0.35f * line), text);
            const std::string label = tick_text(t, spacing);
            const float w = ImGui::CalcTextSize(label.c_str()).x;
            const float left = std::clamp(x - w / 2, p.x, p.x + width - w);
            if (left < free_from) continue;
            draw->AddText(ImVec2(left, p.y + bar_h + 0.35f * line), text, label.c_str());
            free_from = left + w + 0.5f * line;
        }
        ImGui::Dummy(ImVec2(width, bar_h + 1.45f * line));
        for (const LegendMark& m : legend.marks)
            ImGui::TextColored(ImVec4(1.0f, 0.84f, 0.43f, 1.0f), "| %s", mark_text(legend, m).c_str());
    }
    for (const LegendSwatch& s : legend.specials) {
        const ImVec2 p = ImGui::GetCursorScreenPos();
        const float side = ImGui::GetTextLineHeight();
        draw->AddRectFilled(ImVec2(p.x - 1, p.y - 1), ImVec2(p.x + side + 1, p.y + side + 1), frame);
        draw->AddRectFilled(p, ImVec2(p.x + side, p.y + side), to_imgui(s.color));
        ImGui::Dummy(ImVec2(side, side));
        ImGui::SameLine();
        ImGui::TextUnformatted(s.name.c_str());
    }
    if (!legend.note.empty()) {
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
        ImGui::TextDisabled("%s", legend.note.c_str());
        ImGui::PopTextWrapPos();
    }
}

}  // namespace gsv
