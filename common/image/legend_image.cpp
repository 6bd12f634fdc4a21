#include "common/image/legend_image.h"

#include "common/image/text.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace gsv {
namespace {

constexpr Rgba8 kPanel{28, 28, 32, 255};
constexpr Rgba8 kText{236, 236, 236, 255};
constexpr Rgba8 kDim{165, 165, 172, 255};
constexpr Rgba8 kMark{255, 214, 110, 255};
constexpr Rgba8 kFrame{120, 120, 128, 255};
constexpr Rgba8 kPlotGround{46, 46, 52, 255};

Rgba8 opaque(const LegendColor& c) {
    return {static_cast<std::uint8_t>(to_level(c[0])), static_cast<std::uint8_t>(to_level(c[1])),
            static_cast<std::uint8_t>(to_level(c[2])), 255};
}

struct Label {
    double value;
    std::string text;
    bool mark;
};

}  // namespace

double LegendPlacement::value_at_row(const Legend& legend, int y) const {
    const double t = (y + 0.5 - bar[1]) / static_cast<double>(bar[3] - bar[1]);
    return legend.max - t * (legend.max - legend.min);
}

Image with_legend(const Image& image, const Legend& legend, LegendPlacement* placement) {
    check_legend(legend);
    const int px = std::clamp(static_cast<int>(std::lround(image.height / 28.0)), 11, 32);
    const TextSize em = measure_text("Ag", px);
    const int line = em.height + px / 4;
    const int margin = px, gap = std::max(px / 2, 3), tick = std::max(px / 2, 3);
    const bool has_bar = !legend.ramp.empty();
    const int bar_w = has_bar ? static_cast<int>(std::lround(1.4 * px)) : 0;
    const std::string plot_caption = "opacity 0\xE2\x80\x93" "1";
    const int plot_w = has_bar && legend.opacity ? std::max(4 * px, measure_text(plot_caption, px).width) : 0;

    // Labels along the bar: named marks first, so a tick that would overlap one gives way.
    std::vector<Label> labels;
    if (has_bar) {
        for (const LegendMark& m : legend.marks)
            if (m.value >= legend.min && m.value <= legend.max) labels.push_back({m.value, mark_text(legend, m), true});
        const double spacing = tick_spacing(legend.ticks);
        for (double t : legend.ticks)
            if (t >= legend.min && t <= legend.max) labels.push_back({t, tick_text(t, spacing), false});
    }
    int label_w = 0;
    for (const Label& l : labels) label_w = std::max(label_w, measure_text(l.text, px).width);
    const int scale_w = has_bar ? bar_w + (plot_w ? gap + plot_w : 0) + tick + gap / 2 + label_w : 0;
    int content_w = std::max(scale_w, measure_text(legend.heading(), px).width);
    for (const LegendSwatch& s : legend.specials) content_w = std::max(content_w, px + gap + measure_text(s.name, px).width);
    content_w = std::max(content_w, 6 * px);
    const std::vector<std::string> note = wrap_text(legend.note, content_w, px);

    // Heights: heading, bar (at least four lines tall), opacity caption, swatches, note.
    const int top = margin + line + em.height / 2 + px / 2;
    const int below = (plot_w ? line : 0) + em.height / 2 + (legend.specials.empty() ? 0 : px / 2) +
                      static_cast<int>(legend.specials.size()) * (px + px / 3) + (note.empty() ? 0 : px / 2) +
                      static_cast<int>(note.size()) * line + margin;
    const int height = std::max(image.height, top + (has_bar ? 4 * line : 0) + below);
    const int panel_w = content_w + 2 * margin;

    Image out(image.width + panel_w, height);
    fill_rect(out, 0, 0, out.width, out.height, kPanel);
    for (int y = 0; y < image.height; ++y)
        std::copy(image.at(0, y), image.at(0, y) + 4 * static_cast<std::size_t>(image.width), out.at(0, y));

    LegendPlacement where;
    where.font_px = px;
    const int x0 = image.width + margin;
    draw_text(out, x0, margin, legend.heading(), px, kText);
    int y = top;
    if (has_bar) {
        const int y1 = height - below;
        where.bar = {x0, top, x0 + bar_w, y1};
        for (int row = top; row < y1; ++row) {
            const LegendColor c = legend.color_at(where.value_at_row(legend, row));
            fill_rect(out, x0, row, x0 + bar_w, row + 1, opaque(c));
            if (plot_w) {
                const int px0 = x0 + bar_w + gap;
                fill_rect(out, px0, row, px0 + plot_w, row + 1, kPlotGround);
                const int reach = static_cast<int>(std::lround(std::clamp(c[3], 0.0f, 1.0f) * plot_w));
                fill_rect(out, px0, row, px0 + reach, row + 1, opaque(c));
                fill_rect(out, px0 + reach - 1, row, px0 + reach + 1, row + 1, kText);  // the curve itself
            }
        }
        if (plot_w) {
            where.opacity_plot = {x0 + bar_w + gap, top, x0 + bar_w + gap + plot_w, y1};
            draw_text(out, where.opacity_plot[0], y1 + em.height / 2, plot_caption, px, kDim);
        }
        const int scale_right = plot_w ? where.opacity_plot[2] : where.bar[2];
        auto row_of = [&](double v) {
            const double t = (legend.max - v) / (legend.max - legend.min);
            return std::clamp(top + static_cast<int>(std::floor(t * (y1 - top))), top, y1 - 1);
        };
        std::vector<std::pair<int, int>> taken;  // label rows already used
        for (const Label& l : labels) {
            const int row = row_of(l.value);
            const int label_top = row - em.height / 2;
            const bool overlaps = std::any_of(taken.begin(), taken.end(), [&](const std::pair<int, int>& r) {
                return label_top < r.second && label_top + em.height > r.first;
            });
            if (l.mark) {
                // Across the bar and the plot, light over dark so it shows on any colour.
                fill_rect(out, x0 - 2, row - 1, scale_right + 2, row + 2, {0, 0, 0, 255});
                fill_rect(out, x0 - 2, row, scale_right + 2, row + 1, kMark);
            } else {
                fill_rect(out, scale_right, row, scale_right + tick, row + 1, kText);
            }
            if (overlaps) continue;
            taken.emplace_back(label_top, label_top + em.height);
            draw_text(out, scale_right + tick + gap / 2, label_top, l.text, px, l.mark ? kMark : kText);
        }
        y = y1 + em.height / 2 + (plot_w ? line : 0);
    }
    if (!legend.specials.empty()) y += px / 2;
    for (const LegendSwatch& s : legend.specials) {
        fill_rect(out, x0 - 1, y - 1, x0 + px + 1, y + px + 1, kFrame);
        fill_rect(out, x0, y, x0 + px, y + px, opaque(s.color));
        where.swatches.push_back({x0, y, x0 + px, y + px});
        draw_text(out, x0 + px + gap, y + (px - em.height) / 2, s.name, px, kText);
        y += px + px / 3;
    }
    if (!note.empty()) y += px / 2;
    for (const std::string& text : note) {
        draw_text(out, x0, y, text, px, kDim);
        y += line;
    }
    if (placement) *placement = std::move(where);
    return out;
}

}  // namespace gsv
