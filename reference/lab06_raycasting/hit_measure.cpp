#include "hit_measure.h"

#include "reference/volume/gradient.h"
#include "support/geometry/ray_box.h"
#include "sources.h"
#include "support/volume/marschner_lobb.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace lab06 {
namespace {

glm::dvec3 unproject(const glm::dmat4& inverse, double x, double y, double z) {
    const glm::dvec4 p = inverse * glm::dvec4(x, y, z, 1.0);
    return glm::dvec3(p) / p.w;
}

}  // namespace

gsv::SweepMetrics measure_hits(gsv::LabKit& kit, const RayTraversal& raycaster, const FrameView& view) {
    using Config = gsv::RaycastConfig;
    const gsv::Params& p = kit.params();
    // The network built in code, whose ray caster follows the lab's parameters: its configuration is theirs.
    const Config config = raycaster.config();
    if (gsv::parse_enum(kVolumeKinds, "volume", p.get_choice("volume")) != VolumeKind::MarschnerLobb ||
        config.compositing != Config::Compositing::Isosurface || p.get_bool("probe") || !p.get_file("network").empty() ||
        p.get_vec3("clip_normal") != glm::vec3(0.0f) || !raycaster.image())
        return {};
    const gsv::Volume volume = gsv::make_marschner_lobb_volume(p.get_int("ml_size"));
    const bool normals = config.gradient == Config::Gradient::Forward || config.gradient == Config::Gradient::Central;
    const double iso = p.get_float("iso_value");
    const ImageData& image = *raycaster.image();
    const std::vector<float> depth = kit.read_depth(image);
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(view.projection) * glm::dmat4(view.view));
    const glm::dvec3 eye(view.eye);

    double sum2 = 0, worst = 0, angle2 = 0;
    int both = 0, one = 0, rays = 0, on_surface = 0;
    for (int y = 0; y < image.height(); y += 4)
        for (int x = 0; x < image.width(); x += 4) {
            const double nx = 2.0 * (x + 0.5) / image.width() - 1.0;
            const double ny = 1.0 - 2.0 * (y + 0.5) / image.height();  // row 0 is the top
            const glm::dvec3 far = unproject(inverse, nx, ny, 1.0);
            std::optional<double> exact = gsv::marschner_lobb_ray_hit(eye, far - eye, 0.0, 1.0, iso);
            bool cut_face = false;
            // A ray that enters the box where rho >= iso already (the bottom face, z = -1, is inside the
            // surface) hits at its entry, as the isosurface module says: the object is cut open there.
            if (const auto span = gsv::ray_box_span(eye, far - eye, glm::dvec3(-1.0), glm::dvec3(1.0))) {
                const double entry = std::max(span->entry, 0.0);
                if (entry <= span->exit && gsv::marschner_lobb(eye + entry * (far - eye)) >= iso) {
                    exact = entry;
                    cut_face = true;
                }
            }
            const float d = depth[static_cast<std::size_t>(y) * image.width() + x];
            ++rays;
            if (!exact && d >= 1.0f) continue;
            if (!exact || d >= 1.0f) {
                ++one;
                continue;
            }
            const glm::dvec3 hit = unproject(inverse, nx, ny, 2.0 * d - 1.0);
            const glm::dvec3 truth = eye + *exact * (far - eye);
            const double e = glm::length(hit - truth);
            sum2 += e * e;
            worst = std::max(worst, e);
            ++both;
            // On a cut face the surface is the box, not rho = iso, and differences there reach past the
            // edge, where the texture clamps: the schemes are compared on the isosurface only.
            if (normals && !cut_face) {
                const glm::dvec3 t = gsv::marschner_lobb_texcoord(hit);
                const glm::dvec3 g = config.gradient == Config::Gradient::Forward ? gsv::forward_difference(volume, t)
                                                                                    : gsv::central_difference(volume, t);
                const glm::dvec3 exact_g = gsv::marschner_lobb_gradient(hit);  // same point: the scheme alone
                const double c = glm::dot(gsv::safe_normalize(g), gsv::safe_normalize(exact_g));
                const double a = std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / 3.141592653589793;
                angle2 += a * a;
                ++on_surface;
            }
        }
    gsv::SweepMetrics m;
    m.emplace_back("iso_err_rms", both ? std::sqrt(sum2 / both) : 0.0);
    m.emplace_back("iso_err_max", worst);
    m.emplace_back("iso_missed", rays ? static_cast<double>(one) / rays : 0.0);
    if (normals) m.emplace_back("normal_err_deg", on_surface ? std::sqrt(angle2 / on_surface) : 0.0);
    return m;
}

}  // namespace lab06
