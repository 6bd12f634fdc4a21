// Lab 07: rendering spectral (high-order) elements directly, per fragment.
// Seed: Peng and Forsberg, "Directly Rendering Spectral Elements Using Texture Shaders" (Brown CS-02-17, 2002).
// Each element carries its field's values at (p + 1)^2 nodes; every fragment evaluates the element's
// degree-p Lagrange polynomial at its own reference point (spectral.glsl), with no tessellation of the field
// and no texture per element: the basis (nodes and barycentric weights) is 2 (p + 1) uniform floats, the
// values one buffer. Beside it, the same elements drawn from their corner values only.
#include "common/app/app.h"
#include "common/core/number_text.h"
#include "common/app/legend_probe.h"
#include "common/gl/gl.h"
#include "element_data.h"
#include "element_measure.h"
#include "sweep_view.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace {

enum class Evaluation { Full, Corners, Basis };
constexpr gsv::EnumName<Evaluation> kEvaluations[] = {
    {Evaluation::Full, "full"}, {Evaluation::Corners, "corners"}, {Evaluation::Basis, "basis"}};

class SpectralLab final : public gsv::Lab, public lab07::SweepView {
public:
    gsv::LabInfo info() const override { return {"lab07", "Rendering spectral elements"}; }

    void declare(gsv::Params& p) override {
        lab07::ElementParams& e = element_params_;
        using Shape = gsv::ElementMesh::Shape;
        e.mesh = p.add_enum("mesh", Shape::Annulus, gsv::ElementMesh::kShapeNames,
                            "curved elements around a ring, or square elements tiling [-1,1]^2");
        e.columns = p.add_int("columns", 32, 1, 4096, "elements around the ring (annulus) or across (grid)");
        e.rows = p.add_int("rows", 4, 1, 4096, "elements across the ring (annulus) or up (grid)");
        e.inner_radius = p.add_float("inner_radius", 0.35, 0, 0.95, "the annulus's inner radius (the outer is 1)")
                             .with_step(0.05)
                             .applies_when(e.mesh, {Shape::Annulus});
        e.field = p.add_enum("field", gsv::SpectralField::Waves, gsv::kSpectralFieldNames,
                             "travelling waves; Runge's function; a polynomial of degree 3 per variable");
        e.degree = p.add_int("degree", 4, 1, 16, "p: the polynomial degree per axis, p + 1 nodes per axis (the seed's order p - 1)")
                       .at_compile_time()
                       .accuracy_knob({"1", "2", "3", "4", "6", "8", "12", "16"});
        e.node_set = p.add_enum("node_set", gsv::NodeSet::GaussLobattoLegendre, gsv::kNodeSetNames,
                                "Gauss-Lobatto-Legendre or equispaced nodes").series();
        evaluation_ = p.add_enum("evaluation", Evaluation::Full, kEvaluations,
                                           "the polynomial per fragment, the bilinear blend of each element's corner values, "
                                           "or one basis function l_k(xi) in grey across every element").at_compile_time();
        p.add_int("basis_index", 1, 0, 16, "k: the basis function drawn (evaluation=basis), clamped to the degree")
            .applies_when(evaluation_, {Evaluation::Basis});
        e.subdivisions = p.add_int("subdivisions", 6, 1, 64, "quads per element side, to follow curved elements (the field is per fragment)");
        e.time = p.add_float("time", 0, 0, 6.2832, "the field's time: play it in the window").with_step(0.05).animated();
        auto_range_ = p.add_bool("auto_range", true, "colour range from the smallest to the largest node value");
        range_min_ = p.add_float("range_min", -1, -100, 100, "with auto_range off: the value drawn blue").with_step(0.05).applies_when(auto_range_, false);
        range_max_ = p.add_float("range_max", 1, -100, 100, "with auto_range off: the value drawn red").with_step(0.05).applies_when(auto_range_, false);
        element_edges_ = p.add_effect("element_edges", true, "a thin dark line along every element's edges");
        zoom_ = p.add_float("zoom", 1, 0.5, 500, "magnification (1: the whole mesh)").with_step(0.25);
        centre_x_ = p.add_float("centre_x", 0, -1.2, 1.2, "the point looked at").with_step(0.02);
        centre_y_ = p.add_float("centre_y", 0, -1.2, 1.2, "the point looked at").with_step(0.02);
    }

    void setup(gsv::LabKit& kit) override {
        programs_.color = &kit.program("element", {"element.vert", "element.frag"});
        programs_.corners = &kit.program("element_corners", {"element.vert", "corners_probe.frag"});
        programs_.probe = &kit.program("value_probe", {"element.vert", "value_probe.frag"});
    }

    void render(gsv::LabKit& kit, const gsv::Frame& frame) override {
        lab07::update_element_data(data_, kit, element_params_);
        glDisable(GL_DEPTH_TEST);
        glClearColor(0.12f, 0.12f, 0.14f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        const gsv::ShaderProgram& program = kit.use(*programs_.color);
        kit.set_transforms(program, transforms(frame));
        data_.bind(program);
        if (auto_range_.get()) {
            program.set("uRangeMin", data_.min_value);
            program.set("uRangeMax", data_.max_value);
        }
        data_.patches.draw();
    }

    // The field's colours as color_map.glsl gives them over the range drawn, and its colours outside that range.
    std::optional<gsv::Legend> legend(gsv::LabKit& kit) override {
        lab07::update_element_data(data_, kit, element_params_);
        const bool automatic = auto_range_.get();
        const float low = automatic ? data_.min_value : range_min_.get();
        const float high = automatic ? data_.max_value : range_max_.get();
        const auto set_range = [&](const gsv::ShaderProgram& program) {
            program.set("uRangeMin", low);
            program.set("uRangeMax", high);
        };
        gsv::Legend legend;
        legend.title = "value of " + element_params_.field.param().get();
        legend.min = low;
        legend.max = high;
        legend.note = automatic ? "Range: the smallest to the largest node value (auto_range)." : "Range: range_min to range_max.";
        if (element_edges_.get()) legend.note += " Dark lines: element edges.";
        if (!(high > low)) {
            legend.specials.push_back({"empty range (max <= min)", legend_probe_.colors(kit, {low}, set_range)[0]});
            return legend;
        }
        legend.ramp = legend_probe_.ramp(kit, low, high, 256, set_range);
        legend.ticks = gsv::nice_ticks(low, high);
        const double span = high - low;
        const std::vector<gsv::LegendColor> outside = legend_probe_.colors(kit, {low - span, high + span}, set_range);
        legend.specials.push_back({"below the range", outside[0]});
        legend.specials.push_back({"above the range", outside[1]});
        return legend;
    }

    // spectral.glsl a fragment, with n = degree + 1 nodes: the basis in xi and in eta (n subtractions, divisions and
    // additions each, then n divisions: 4n flops each), then the tensor sum, n^2 multiply-adds of n^2 node values
    // and n more: 2n^2 + 10n flops. At most one fragment a pixel.
    gsv::FrameWork frame_work(const gsv::Frame& frame) const override {
        const double n = element_params_.degree.get() + 1;
        const double fragments = static_cast<double>(frame.width) * frame.height;
        gsv::FrameWork work;
        work.upper_bound = true;
        if (evaluation_.get() == Evaluation::Full) {
            work.items.push_back({gsv::WorkKind::Flops, gsv::ShaderPath::Fragment, "", fragments * (2 * n * n + 10 * n),
                                  "2n^2 + 10n a fragment, n = " + gsv::format_number(n, 3)});
            work.items.push_back({gsv::WorkKind::Fetch, gsv::ShaderPath::Fragment, "R32F buffer", fragments * n * n,
                                  "n^2 node values a fragment (texelFetch), n = " + gsv::format_number(n, 3)});
        } else {
            work.items.push_back({gsv::WorkKind::Fragments, gsv::ShaderPath::Fragment, "", fragments,
                                  "one fragment a pixel at most"});
        }
        return work;
    }

    // What its sweep plan reads (sweep_view.h).
    const lab07::ElementData& element_data() const override { return data_; }
    const lab07::MeasurePrograms& measure_programs() const override { return programs_; }

private:
    // A 2D view: the mesh spans [-1, 1]^2; zoom about (centre_x, centre_y), the aspect kept.
    gsv::Transforms transforms(const gsv::Frame& frame) const override {
        const float half = 1.08f / zoom_.get();
        const float aspect = frame.aspect();
        const glm::vec2 c(centre_x_.get(), centre_y_.get());
        gsv::Transforms t;
        t.projection = glm::ortho(c.x - half * std::max(aspect, 1.0f), c.x + half * std::max(aspect, 1.0f),
                                  c.y - half / std::min(aspect, 1.0f), c.y + half / std::min(aspect, 1.0f), -1.0f, 1.0f);
        return t;
    }

    lab07::ElementParams element_params_;
    gsv::EnumParam<Evaluation> evaluation_;
    gsv::Param<bool> auto_range_, element_edges_;
    gsv::Param<float> range_min_, range_max_, zoom_, centre_x_, centre_y_;
    lab07::MeasurePrograms programs_;
    lab07::ElementData data_;
    gsv::LegendProbe legend_probe_{"legend_probe.frag"};
};

}  // namespace

int main(int argc, char** argv) { return gsv::run_lab<SpectralLab>(argc, argv); }
