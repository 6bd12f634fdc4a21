#include "common/app/live_controls.h"

#include "common/core/number_text.h"

#include <algorithm>
#include <cmath>

namespace gsv {
namespace {

bool has_param(const Params& params, const std::string& name) {
    for (const auto& s : params.specs())
        if (s.name == name) return true;
    return false;
}

void adjust(Params& params, const std::string& name, double delta) {
    const ParamSpec& s = params.spec(name);
    params.set(name, std::to_string(std::clamp(params.get_float(name) + delta, s.min, s.max)));
}

}  // namespace

void play_animation(Params& params, double seconds) {
    const ParamSpec* axis = params.animation_axis();
    if (!axis || !(axis->max > axis->min)) return;
    const double span = axis->max - axis->min;
    double v = params.get_float(axis->name) + span / 8 * seconds;
    if (v > axis->max) v = axis->min + std::fmod(v - axis->min, span);
    params.set(axis->name, format_number(std::clamp(v, axis->min, axis->max), 9));
}

bool orbit_drag(Params& params, double dx, double dy) {
    if (!has_param(params, "camera_yaw")) return false;
    adjust(params, "camera_yaw", -0.4 * dx);
    adjust(params, "camera_pitch", 0.4 * dy);
    return true;
}

bool orbit_zoom(Params& params, double steps) {
    if (!has_param(params, "camera_distance")) return false;
    adjust(params, "camera_distance", -0.2 * steps);
    return true;
}

}  // namespace gsv
