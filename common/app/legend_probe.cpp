#include "common/app/legend_probe.h"

#include "common/core/error.h"
#include "common/gl/gl.h"
#include "common/gl/texture.h"

#include <algorithm>
#include <cmath>

namespace gsv {
std::vector<LegendColor> LegendProbe::colors(LabKit& kit, const std::vector<double>& values,
                                             const std::function<void(const ShaderProgram&)>& set_uniforms) {
    if (values.empty()) return {};
    const int count = static_cast<int>(values.size());
    const std::vector<float> texels(values.begin(), values.end());
    const Texture value_texture =
        Texture::create_2d(count, 1, TexelFormat::R32F, texels.data(), Sampling{GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE});
    const ImageF pixels = probe_.draw(kit, count, 1, [&](const ShaderProgram& program) {
        program.bind("uLegendValues", value_texture);
        if (set_uniforms) set_uniforms(program);
    }, "drawing the legend probe");
    std::vector<LegendColor> out;
    out.reserve(values.size());
    for (int i = 0; i < count; ++i) {
        const float* p = pixels.at(i, 0);
        LegendColor c{};
        const bool nan = std::isnan(p[0]) || std::isnan(p[1]) || std::isnan(p[2]) || std::isnan(p[3]);
        for (std::size_t k = 0; k < 4; ++k) c[k] = nan ? (k == 1 ? 0.0f : 1.0f) : std::clamp(p[k], 0.0f, 1.0f);
        out.push_back(c);
    }
    return out;
}

std::vector<LegendStop> LegendProbe::ramp(LabKit& kit, double min, double max, int count,
                                          const std::function<void(const ShaderProgram&)>& set_uniforms) {
    if (count < 2) throw Error("a legend ramp needs at least 2 stops, asked for " + std::to_string(count));
    std::vector<double> values;
    for (int i = 0; i < count; ++i) values.push_back(i + 1 == count ? max : min + (max - min) * i / (count - 1));
    const std::vector<LegendColor> sampled = colors(kit, values, set_uniforms);
    std::vector<LegendStop> stops;
    for (int i = 0; i < count; ++i) stops.push_back({values[static_cast<std::size_t>(i)], sampled[static_cast<std::size_t>(i)]});
    return stops;
}

}  // namespace gsv
