#include "catch.hpp"

#include "common/core/error.h"
#include "support/flow/flow_field.h"
#include "support/flow/moving_frame.h"
#include "test_support.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <limits>
#include <string>

using gsv::FlowField;

namespace {

// The turning of the field around each cell of four texel centres, in whole turns: +1 around a centre, a node or
// a focus (a vortex seen from its own frame), -1 around a saddle, 0 where the flow just passes (Poincare's index).
struct CriticalPoints {
    int turning = 0;  // +1
    int saddles = 0;  // -1
};

CriticalPoints critical_points(const FlowField& field) {
    CriticalPoints found;
    const auto angle = [&](int x, int y) {
        const glm::vec2 v = field.at(x, y);
        return std::atan2(static_cast<double>(v.y), static_cast<double>(v.x));
    };
    const auto wrapped = [](double d) {
        const double pi = glm::pi<double>();
        while (d > pi) d -= 2 * pi;
        while (d < -pi) d += 2 * pi;
        return d;
    };
    for (int y = 0; y + 1 < field.height; ++y)
        for (int x = 0; x + 1 < field.width; ++x) {
            const double a[4] = {angle(x, y), angle(x + 1, y), angle(x + 1, y + 1), angle(x, y + 1)};
            double turn = 0;
            for (int i = 0; i < 4; ++i) turn += wrapped(a[(i + 1) % 4] - a[i]);
            const long index = std::lround(turn / (2 * glm::pi<double>()));
            found.turning += index == 1;
            found.saddles += index == -1;
        }
    return found;
}

}  // namespace

TEST_CASE("moving frame: the observer's velocity is taken off every texel's x velocity, and must be finite", "[unit][flow]") {
    FlowField field;
    field.width = 2;
    field.height = 1;
    field.velocity = {1.0f, 0.5f, -0.25f, 0.0f};
    const FlowField seen = gsv::seen_from_moving_frame(field, 0.75);
    CHECK(seen.velocity == std::vector<float>{0.25f, 0.5f, -1.0f, 0.0f});
    const gsv::VelocityAt everywhere = gsv::seen_from_moving_frame([](glm::dvec2 q) { return q; }, 0.75);
    CHECK(everywhere(glm::dvec2(2.0, 3.0)) == glm::dvec2(1.25, 3.0));
    CHECK(gsv::test::gsv_error_message([&] { gsv::seen_from_moving_frame(field, std::nan("")); })
              .find("observer's velocity must be finite") != std::string::npos);
    CHECK_THROWS_AS(gsv::seen_from_moving_frame(field, std::numeric_limits<double>::infinity()), gsv::Error);
}

TEST_CASE("moving frame: the vortex street shows its vortices only to an observer moving with them", "[unit][flow]") {
    // The street as data/flows/vortex_street.flow holds it: 128 x 64 texels over [0,2]x[0,1], so a domain unit of
    // velocity along x is 64 texels per step before the sequence is scaled to its largest speed.
    const gsv::FlowSequence street = gsv::make_vortex_street(128, 64, 16, 1.0);
    const FlowField& frame = street.frames[5];
    const double scale = frame.at(40, 10).x / (64.0 * gsv::vortex_street_velocity({2.0 * 40.5 / 128, 10.5 / 64}, 5.0 / 16).x);
    const double drift = gsv::vortex_street_drift() * 64.0 * scale;
    const CriticalPoints at_rest = critical_points(frame);
    const CriticalPoints moving = critical_points(gsv::seen_from_moving_frame(frame, drift));
    INFO("drift " << drift << " texels per step; turning points at rest " << at_rest.turning << ", moving "
                  << moving.turning << "; saddles " << at_rest.saddles << ", " << moving.saddles);
    CHECK(at_rest.turning == 0);
    CHECK(at_rest.saddles == 0);
    // Four vortices a row across the domain's length of 2, a spacing of 0.5 apart: a centre each, and a saddle
    // between each vortex and the next of the other row.
    CHECK(moving.turning == 8);
    CHECK(moving.saddles == 8);
}
