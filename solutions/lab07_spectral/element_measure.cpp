#include "element_measure.h"

#include "common/app/sweep_metrics.h"
#include "common/gl/gl.h"
#include "common/timing/timing.h"

namespace lab07 {

void draw_elements(gsv::LabKit& kit, const ElementData& data, const gsv::ShaderLibrary::Entry& entry,
                   const gsv::Transforms& transforms, const gsv::Framebuffer& target) {
    target.bind();
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    const gsv::ShaderProgram& program = kit.use(entry);
    kit.set_transforms(program, transforms);
    data.bind(program);
    program.set("uRangeMin", data.min_value);
    program.set("uRangeMax", data.max_value);
    data.patches.draw();
}

gsv::SweepMetrics measure_costs(gsv::LabKit& kit, const ElementData& data, const MeasurePrograms& programs,
                                const gsv::Transforms& transforms, int width, int height) {
    gsv::Framebuffer target(width, height, gsv::ColorFormat::RGBA32F, false);
    // The two shaders timed in turns, so that whatever else the machine does falls on both alike.
    const gsv::InterleavedTimes times = gsv::time_interleaved(
        {{nullptr, [&] { draw_elements(kit, data, *programs.color, transforms, target); }},
         {nullptr, [&] { draw_elements(kit, data, *programs.corners, transforms, target); }}},
        gsv::kCompareWarmup, gsv::kCompareFrames, gsv::kCompareRounds);
    gsv::SweepMetrics m;
    gsv::add_time(m, "drawn_ms", times.stats[0]);
    gsv::add_time(m, "corner_ms", times.stats[1]);
    gsv::add_ratio(m, "rate_vs_corners", times.ratio(1, 0));
    m.emplace_back("basis_bytes", static_cast<double>(data.basis_bytes()));
    m.emplace_back("value_bytes", static_cast<double>(data.value_texture.bytes()));
    return m;
}

}  // namespace lab07
