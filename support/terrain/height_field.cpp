// HeightField's accessors; reading and writing .height files are in height_file.cpp and
// height_file_save.cpp.
#include "support/terrain/height_field.h"

#include "common/core/error.h"

#include <algorithm>
#include <string>

namespace gsv {
namespace {

void check_inside(const HeightField& field, int x, int y, const char* who) {
    if (x < 0 || y < 0 || x >= field.width || y >= field.height)
        throw Error(std::string(who) + ": sample (" + std::to_string(x) + ", " + std::to_string(y) +
                    ") is outside the " + std::to_string(field.width) + "x" + std::to_string(field.height) + " grid");
}

}  // namespace

float HeightField::at(int x, int y) const {
    check_inside(*this, x, y, "HeightField::at");
    return heights[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
}

float HeightField::min_height() const {
    return heights.empty() ? 0.0f : *std::min_element(heights.begin(), heights.end());
}

float HeightField::max_height() const {
    return heights.empty() ? 0.0f : *std::max_element(heights.begin(), heights.end());
}

glm::dvec2 sample_position(const HeightField& field, int x, int y) {
    check_inside(field, x, y, "sample_position");
    return {(x + 0.5) * field.dx_m, (y + 0.5) * field.dy_m};
}

}  // namespace gsv
