#pragma once
// A legend where colour is data: what a colour stands for (a height, a speed, an intensity's colour and opacity),
// over which values, with which ticks, and the colours that stand for no value on the scale ("below the range").
// A lab builds it from the numbers its shaders use (Lab::legend, common/app/app.h); `render --legend` draws it
// beside the image (common/image/legend_image.h) and the window's panel draws it live.
#include <array>
#include <string>
#include <vector>

namespace gsv {

// Straight (not premultiplied) RGB in [0, 1]; alpha is the opacity where the legend has one, else 1.
using LegendColor = std::array<float, 4>;

struct LegendStop {
    double value = 0;
    LegendColor color{0, 0, 0, 1};
};

// A named value on the scale: "tree line", "iso value".
struct LegendMark {
    double value = 0;
    std::string name;
};

// A colour that is not a value of the scale: "below the range", "no data".
struct LegendSwatch {
    std::string name;
    LegendColor color{0, 0, 0, 1};
};

struct Legend {
    std::string title;  // what the colour stands for: "height", "speed"
    std::string unit;   // "m", "1/s"; empty for a quantity without one
    double min = 0, max = 1;       // the ends of the bar
    // Ascending values in [min, max]: the colour is linear between neighbours and the end colour beyond them, as a
    // linearly filtered texture clamped to its edge reads. Empty: the scale has no colours (only swatches).
    std::vector<LegendStop> ramp;
    bool opacity = false;              // alpha is data (a transfer function's opacity), drawn as a curve
    std::vector<double> ticks;         // values labelled along the bar
    std::vector<LegendMark> marks;
    std::vector<LegendSwatch> specials;
    std::string note;                  // what the picture does to these colours ("unlit: the image shades them")

    LegendColor color_at(double value) const;
    std::string heading() const;       // "height (m)"
};

// Throws gsv::Error naming what is wrong: a ramp over an empty or non-finite range, stops out of order or outside
// [min, max], a colour channel outside [0, 1].
void check_legend(const Legend& legend);

// Round values (1, 2 or 5 times a power of ten apart) within [min, max], at most `at_most` of them.
std::vector<double> nice_ticks(double min, double max, int at_most = 6);

// A tick's text with as many decimals as the spacing of its ticks needs ("0.25", "1500", "-2"); `spacing` 0: %g.
std::string tick_text(double value, double spacing);
// The spacing of a tick list (its smallest gap), 0 for fewer than two ticks.
double tick_spacing(const std::vector<double>& ticks);

// A mark's label: its name and value, to a tenth of the ticks' spacing ("tree line 1756", "iso value 0.50").
std::string mark_text(const Legend& legend, const LegendMark& mark);

// One channel in [0, 1] as the 8-bit level a float render target's readback gives it (common/image/image.h).
int to_level(float channel);

}  // namespace gsv
