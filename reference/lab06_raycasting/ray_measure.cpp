#include "ray_measure.h"

#include "common/app/sweep_metrics.h"
#include "common/timing/timing.h"

#include <string>

namespace lab06 {

gsv::SweepMetrics compare_shaders(RayTraversal& raycaster) {
    // Set on its parameters, not with set_param: not marked as set, so the lab's parameter still leads.
    const Shader chosen = raycaster.shader().get();
    gsv::RaycastConfig dvr;
    dvr.gradient = gsv::RaycastConfig::Gradient::Central;
    dvr.classification = gsv::RaycastConfig::Classification::TransferFunction;
    dvr.shading = gsv::RaycastConfig::Shading::Phong;
    dvr.early_termination = raycaster.config().early_termination;
    std::vector<Shader> shaders{Shader::Specialised, Shader::Uber};
    if (gsv::effective_config(raycast_modules(), raycaster.config()) == dvr) shaders.push_back(Shader::Handwritten);
    const auto choose = [&raycaster](Shader shader) {
        raycaster.params().set(raycaster.shader().name(), raycaster.shader().name_of(shader));
    };
    std::vector<gsv::TimedWork> work;
    for (const Shader shader : shaders)
        work.push_back({[choose, shader] { choose(shader); }, [&raycaster] { raycaster.process(); }});
    gsv::SweepMetrics m;
    try {
        const gsv::InterleavedTimes times = gsv::time_interleaved(work, gsv::kCompareWarmup, gsv::kCompareFrames, gsv::kCompareRounds);
        gsv::add_time(m, "specialised_ms", times.stats[0]);
        gsv::add_time(m, "uber_ms", times.stats[1]);
        gsv::add_ratio(m, "uber_over_specialised", times.ratio(1, 0));
        if (shaders.size() == 3) {
            gsv::add_time(m, "handwritten_ms", times.stats[2]);
            gsv::add_ratio(m, "specialised_over_handwritten", times.ratio(0, 2));
        }
    } catch (...) {
        choose(chosen);
        throw;
    }
    choose(chosen);
    return m;
}

}  // namespace lab06
