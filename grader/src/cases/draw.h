#pragma once
// Hidden cases draw their parameters from a seed given at grading time, so an image baked into a
// submission cannot match. The same seed draws the same cases on every machine (our own splitmix64,
// not the standard library's distributions, whose output differs between implementations).
#include "common/io/json.h"

#include <cstdint>
#include <string>
#include <vector>

namespace gsv {

class SeededDraw {
public:
    // `stream` tells apart what is drawn for each case from the same seed (e.g. "lab01/hidden-phong/2").
    SeededDraw(std::uint64_t seed, const std::string& stream);
    std::uint64_t next();
    double uniform(double lo, double hi);  // [lo, hi)
    long integer(long lo, long hi);        // [lo, hi]

private:
    std::uint64_t state_;
};

// One "name=value" setting per member of `spec`, e.g.
//   {"light_x": {"range": [-4, 4]}, "steps": {"int": [1, 8]}, "model": {"choice": ["sphere", "torus"]},
//    "light_position": {"vec3": [[-4, 4], [-1, 4], [0.5, 4]]}, "odd": {"int": [1, 99], "step": 2}}
// ("step": every step-th whole number from the low end: a draw can keep off values where a mistake hides, such as a
// count that is a multiple of a work-group size).
// Throws gsv::Error naming the member when a spec is malformed.
// A draw may hold only where another setting has one of some values ("when": "field=double_gyre|file"): it is
// drawn all the same, so the rest of the stream does not depend on it, and kept only then. The other setting must be
// one of `fixed` (the case's own settings) or drawn here; a parameter that would have no effect is refused by the lab.
std::vector<std::string> draw_settings(const Json& spec, SeededDraw& draw, const std::vector<std::string>& fixed = {});

// A seed for when none is given: from the clock and the OS's entropy, printed so the run can be repeated.
std::uint64_t fresh_seed();

}  // namespace gsv
