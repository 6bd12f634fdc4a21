#include "common/image/legend.h"

#include "common/core/error.h"
#include "common/core/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gsv {

LegendColor Legend::color_at(double value) const {
    if (ramp.empty()) return {0, 0, 0, 0};
    if (value <= ramp.front().value) return ramp.front().color;
    if (value >= ramp.back().value) return ramp.back().color;
    const auto upper = std::upper_bound(ramp.begin(), ramp.end(), value,
                                        [](double v, const LegendStop& stop) { return v < stop.value; });
    const LegendStop& a = *(upper - 1);
    const LegendStop& b = *upper;
    const double w = b.value > a.value ? (value - a.value) / (b.value - a.value) : 1.0;
    LegendColor out{};
    for (std::size_t c = 0; c < 4; ++c)
        out[c] = static_cast<float>(a.color[c] + w * (b.color[c] - a.color[c]));
    return out;
}

std::string Legend::heading() const { return unit.empty() ? title : title + " (" + unit + ")"; }

void check_legend(const Legend& legend) {
    const std::string who = "legend '" + legend.title + "'";
    if (!legend.ramp.empty() && !(std::isfinite(legend.min) && std::isfinite(legend.max) && legend.max > legend.min))
        throw Error(who + ": its range [" + format_number(legend.min) + ", " + format_number(legend.max) +
                    "] is empty or not finite");
    auto check_color = [&](const LegendColor& color, const std::string& where) {
        for (float c : color)
            if (!(c >= 0.0f && c <= 1.0f)) throw Error(who + ": " + where + " has a channel " + format_number(c) + " outside [0, 1]");
    };
    for (std::size_t i = 0; i < legend.ramp.size(); ++i) {
        const LegendStop& stop = legend.ramp[i];
        const std::string where = "stop " + std::to_string(i) + " at " + format_number(stop.value);
        if (!(stop.value >= legend.min && stop.value <= legend.max))
            throw Error(who + ": " + where + " lies outside [" + format_number(legend.min) + ", " + format_number(legend.max) + "]");
        if (i > 0 && !(stop.value > legend.ramp[i - 1].value)) throw Error(who + ": " + where + " is not above the stop before it");
        check_color(stop.color, where);
    }
    for (const LegendSwatch& swatch : legend.specials) check_color(swatch.color, "'" + swatch.name + "'");
}

std::vector<double> nice_ticks(double min, double max, int at_most) {
    if (!(max > min) || !std::isfinite(min) || !std::isfinite(max) || at_most < 2) return {};
    const double rough = (max - min) / (at_most - 1);
    const double power = std::pow(10.0, std::floor(std::log10(rough)));
    double step = 10 * power;
    for (double factor : {1.0, 2.0, 5.0})
        if (factor * power >= rough) {
            step = factor * power;
            break;
        }
    std::vector<double> ticks;
    // Tolerate rounding at the ends: a tick at 0.3 of [0, 0.3] must not be lost to 0.30000000000000004.
    const double slack = step * 1e-9;
    for (double k = std::ceil((min - slack) / step); k * step <= max + slack; k += 1) {
        const double v = k * step;
        ticks.push_back(std::abs(v) < slack ? 0.0 : v);
    }
    return ticks;
}

std::string tick_text(double value, double spacing) {
    if (!(spacing > 0)) return format_number(value, 4);
    // The fewest decimals that write the spacing exactly: 0.25 needs two, 2.5 one, 500 none.
    int decimals = 0;
    for (double scaled = spacing; decimals < 6 && std::abs(scaled - std::round(scaled)) > 1e-6 * scaled; scaled *= 10)
        ++decimals;
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    std::string out = text;
    if (out.find_first_of("123456789") == std::string::npos && out[0] == '-') out.erase(0, 1);  // no "-0"
    return out;
}

double tick_spacing(const std::vector<double>& ticks) {
    double spacing = 0;
    for (std::size_t i = 1; i < ticks.size(); ++i) {
        const double gap = std::abs(ticks[i] - ticks[i - 1]);
        if (gap > 0 && (spacing == 0 || gap < spacing)) spacing = gap;
    }
    return spacing;
}

std::string mark_text(const Legend& legend, const LegendMark& mark) {
    const double spacing = tick_spacing(legend.ticks);
    return mark.name + " " + (spacing > 0 ? tick_text(mark.value, spacing / 10) : format_number(mark.value, 4));
}

int to_level(float channel) { return static_cast<int>(std::lround(std::clamp(channel, 0.0f, 1.0f) * 255.0f)); }

}  // namespace gsv
